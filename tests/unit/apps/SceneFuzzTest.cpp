// Fuzzing the scene parser and validator in process: seeded mutations of the shipped scenes
// (bytes flipped, spans deleted, YAML tokens and extreme values inserted, lines duplicated or
// swapped) go through readSceneText, validateScene and the solver options, as `contactlab run`
// reads them. Every mutant must be refused with an InputError (std::invalid_argument from the
// options is turned into one by loadScene) or accepted; any other exception, a crash, or a
// mutant that takes more than a second is a defect. The suite runs CONTACTLAB_FUZZ_MUTATIONS
// (default 100 000); bench/fuzz.sh runs 10^6 and records the counts in doc/verification.md.
#include "algorithms/StaticSolver.hpp"
#include "apps/SceneSchema.hpp"
#include "base/InputError.hpp"
#include "core/io/SceneFile.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <random>
#include <sstream>

namespace contactlab {
namespace {

std::vector<std::string> shippedScenes() {
  std::vector<std::string> texts;
  for (const auto& entry : std::filesystem::directory_iterator(CONTACTLAB_SCENES_DIR))
    if (entry.path().extension() == ".yaml") {
      std::ifstream in(entry.path());
      std::stringstream s;
      s << in.rdbuf();
      texts.push_back(s.str());
    }
  return texts;
}

const std::vector<std::string> kTokens = {":",
                                          " ",
                                          "\n",
                                          "\t",
                                          "  ",
                                          "{",
                                          "}",
                                          "[",
                                          "]",
                                          ",",
                                          "-",
                                          "#",
                                          "\"",
                                          "'",
                                          "&a",
                                          "*a",
                                          "!!str ",
                                          "|",
                                          ">",
                                          "?",
                                          "0",
                                          "-1",
                                          "1e308",
                                          "-1e308",
                                          "1e-320",
                                          "nan",
                                          "inf",
                                          "-inf",
                                          "2147483648",
                                          "99999999999999999999",
                                          "0x10",
                                          "true",
                                          "null",
                                          "~",
                                          "{}",
                                          "[]",
                                          "''",
                                          "Type: ",
                                          "Type: mortar",
                                          "xyz",
                                          "z",
                                          "Steps: 0",
                                          "nx: 100000",
                                          "Radius: 1e30",
                                          "E: -1",
                                          "nu: 0.5",
                                          "Friction: -1",
                                          "Max Cuts: -1",
                                          "\xff",
                                          "\xc3\x28",
                                          "contactlab:",
                                          "<<: *a"};

std::string mutate(std::string text, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> count(1, 4);
  const int n = count(rng);
  for (int m = 0; m < n && !text.empty(); ++m) {
    const auto at = [&](std::size_t size) {
      return std::uniform_int_distribution<std::size_t>(0, size)(rng);
    };
    std::size_t i = at(text.size() - 1);
    switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
      case 0:  // a byte flipped to a printable character or a control one
        text[i] = static_cast<char>(std::uniform_int_distribution<int>(1, 126)(rng));
        break;
      case 1:  // a span deleted
        text.erase(i, 1 + at(15));
        break;
      case 2:  // a token inserted
        text.insert(i, kTokens[at(kTokens.size() - 1)]);
        break;
      case 3: {  // a line duplicated
        const std::size_t start =
            text.rfind('\n', i) == std::string::npos ? 0 : text.rfind('\n', i) + 1;
        const std::size_t end = text.find('\n', i);
        const std::string line = text.substr(start, end == std::string::npos ? end : end - start);
        text.insert(start, line + "\n");
        break;
      }
      case 4: {  // a number replaced by an extreme
        const std::size_t digit = text.find_first_of("0123456789", i);
        if (digit == std::string::npos) break;
        const std::size_t end = text.find_first_not_of("0123456789.e-", digit);
        const char* extremes[] = {"0", "-1", "1e308", "nan", "1e-320", "2147483648", "1e9"};
        text.replace(digit, end == std::string::npos ? end : end - digit, extremes[at(6)]);
        break;
      }
      default: {  // two characters swapped (indentation and nesting)
        std::swap(text[i], text[at(text.size() - 1)]);
        break;
      }
    }
  }
  return text;
}

enum class Verdict { accepted, refused, defect };

Verdict check(const std::string& text, std::string& what) {
  try {
    SceneFile scene = readSceneText(text, "fuzz.yaml");
    validateScene(*scene.params, scene.path);
    auto& p = *scene.params;
    StaticSolverOptions::from(p.sublist("Load Steps"), p.sublist("Newton"), p.sublist("Algorithm"));
    return Verdict::accepted;
  } catch (const InputError&) {
    return Verdict::refused;
  } catch (const std::invalid_argument&) {  // the options' checks (loadScene names the file)
    return Verdict::refused;
  } catch (const std::exception& e) {
    what = std::string("exception ") + typeid(e).name() + ": " + e.what();
  } catch (...) {
    what = "a non-standard exception";
  }
  return Verdict::defect;
}

TEST(SceneFuzz, EveryMutantIsRefusedWithASentenceOrAccepted) {
  registerAll();
  const std::vector<std::string> scenes = shippedScenes();
  ASSERT_GE(scenes.size(), 10u);
  const char* env = std::getenv("CONTACTLAB_FUZZ_MUTATIONS");
  const long long mutations = env ? std::atoll(env) : 100000;
  const char* seedEnv = std::getenv("CONTACTLAB_FUZZ_SEED");
  std::mt19937_64 rng(seedEnv ? std::strtoull(seedEnv, nullptr, 10) : 20261123ULL);
  long long accepted = 0, refused = 0, defects = 0;
  double slowest = 0;
  const auto start = std::chrono::steady_clock::now();
  for (long long k = 0; k < mutations; ++k) {
    const std::string text = mutate(scenes[k % scenes.size()], rng);
    std::string what;
    const auto t0 = std::chrono::steady_clock::now();
    const Verdict v = check(text, what);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    slowest = std::max(slowest, seconds);
    if (v == Verdict::accepted) ++accepted;
    if (v == Verdict::refused) ++refused;
    if (v == Verdict::defect && ++defects <= 5)
      ADD_FAILURE() << "mutant " << k << ": " << what << "\n--- scene ---\n" << text;
    EXPECT_LT(seconds, 1.0) << "mutant " << k << " took " << seconds << " s\n" << text;
  }
  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "fuzz: " << mutations << " mutations of " << scenes.size() << " scenes: " << accepted
            << " accepted, " << refused << " refused with a sentence, " << defects
            << " defects; slowest " << slowest << " s, total " << total << " s\n";
  EXPECT_EQ(defects, 0);
  EXPECT_GT(refused, 0);  // the mutations do reach the checks
  EXPECT_GT(accepted, 0);
}

}  // namespace
}  // namespace contactlab
