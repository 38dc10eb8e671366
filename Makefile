# contactlab: two commands.
#   make run    install missing Debian packages, build, run the quick comparison (formulations
#               x algorithm presets x discretizations on a small contact scene, under a minute)
#               and print its table; `make run SCENE=scenes/x.yaml` runs that one scene instead
#   make test   install missing Debian packages, build, run every test (unit, verification, mpi)
# and `make install [PREFIX=/usr/local]`: the command, the libraries for find_package(contactlab)
# and the Python module (PREFIX/lib/python3/dist-packages/contactlab: `import contactlab`).
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
SCENE ?=
STUDY ?= scenes/studies/quick-comparison.yaml
STUDY_ARGS ?=
CTEST_ARGS ?=
PREFIX ?= /usr/local

.PHONY: run test build deps configure clean format bench docs install

# Missing packages: a line per phase, apt's output in $(BUILD_DIR)/install-deps.log.
deps:
	@CONTACTLAB_DEPS_LOG=$(BUILD_DIR)/install-deps.log ./cmake/install-deps.sh

$(BUILD_DIR)/build.ninja: | deps
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release

configure: deps $(BUILD_DIR)/build.ninja

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The study resumes: a second `make run` reuses the runs already in its folder (delete it, or
# pass --retry-failed through STUDY_ARGS, to run them again).
run: build
ifeq ($(SCENE),)
	$(BUILD_DIR)/apps/contactlab study $(STUDY) --out $(BUILD_DIR)/$(basename $(notdir $(STUDY))) $(STUDY_ARGS)
else
	$(BUILD_DIR)/apps/contactlab run $(SCENE)
endif

# ctest runs $(JOBS) tests at once, which fills the cores: one BLAS thread per test process
# (a run alone gives its rank every core it may use, linear/BlasThreads.hpp).
test: build
	cd $(BUILD_DIR) && OPENBLAS_NUM_THREADS=1 ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

install: build
	cmake --install $(BUILD_DIR) --prefix $(PREFIX)

bench: build
	./bench/run.sh

# Rewrites doc/scenes.md (`contactlab list`) and the generated blocks and figures of
# doc/verification.md and doc/studies.md (doc/generate.py runs the cheap cases, ~3 minutes).
docs: build
	/usr/bin/python3 tests/app/check_scenes_doc.py $(BUILD_DIR)/apps/contactlab doc/scenes.md --update
	/usr/bin/python3 doc/generate.py $(BUILD_DIR)/apps/contactlab

format:
	find core formulations linear algorithms apps tests bench -name '*.cpp' -o -name '*.hpp' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR)
