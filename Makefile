# contactlab: two commands.
#   make run    install missing Debian packages, build, run the default scene
#   make test   install missing Debian packages, build, run every test (unit, verification, mpi)
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
SCENE ?=
CTEST_ARGS ?=

.PHONY: run test build deps configure clean format bench docs

deps:
	@./cmake/install-deps.sh

$(BUILD_DIR)/build.ninja: | deps
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release

configure: deps $(BUILD_DIR)/build.ninja

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

run: build
	$(BUILD_DIR)/apps/contactlab run $(SCENE)

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

bench: build
	./bench/run.sh

docs: build
	/usr/bin/python3 tests/app/check_scenes_doc.py $(BUILD_DIR)/apps/contactlab doc/scenes.md --update

format:
	find core formulations linear algorithms apps tests bench -name '*.cpp' -o -name '*.hpp' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR)
