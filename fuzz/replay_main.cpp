// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The corpus replay driver (no libFuzzer): one executable linking every fuzz target, each
// compiled with FAIR_FUZZ_REPLAY so that its entry is fuzz_<target> (fuzz/fuzz_common.h). `fuzz_replay <target>
// <dir>` runs the target on every file of <dir> (its corpus fuzz/corpus/<target>/); an oracle
// violation aborts with the file named first, so ctest reports which input failed.
// Registered as the ctest tests fuzz_replay_<target>; see doc/fuzzing.md.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int fuzz_read_points(const std::uint8_t*, std::size_t);
extern "C" int fuzz_kappa(const std::uint8_t*, std::size_t);
extern "C" int fuzz_cardinal(const std::uint8_t*, std::size_t);
extern "C" int fuzz_classic(const std::uint8_t*, std::size_t);
extern "C" int fuzz_csr(const std::uint8_t*, std::size_t);
extern "C" int fuzz_shapes(const std::uint8_t*, std::size_t);
extern "C" int fuzz_optimal(const std::uint8_t*, std::size_t);
extern "C" int fuzz_metrics(const std::uint8_t*, std::size_t);
extern "C" int fuzz_conic(const std::uint8_t*, std::size_t);

namespace {

struct Target {
  const char* name;
  int (*run)(const std::uint8_t*, std::size_t);
};

const Target targets[] = {{"read_points", fuzz_read_points},
                          {"kappa", fuzz_kappa},
                          {"cardinal", fuzz_cardinal},
                          {"classic", fuzz_classic},
                          {"csr", fuzz_csr},
                          {"shapes", fuzz_shapes},
                          {"optimal", fuzz_optimal},
                          {"metrics", fuzz_metrics},
                          {"conic", fuzz_conic}};

} // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s <target> <corpus dir>\n", argv[0]);
    return 2;
  }
  const Target* target = nullptr;
  for (const Target& t : targets)
    if (std::strcmp(t.name, argv[1]) == 0) target = &t;
  if (!target) {
    std::fprintf(stderr, "%s: unknown target %s\n", argv[0], argv[1]);
    return 2;
  }
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(argv[2]))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::fprintf(stderr, "%s: no inputs in %s\n", argv[0], argv[2]);
    return 1;
  }
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "%s\n", f.filename().string().c_str());
    target->run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("%s: %zu inputs replayed, no oracle violated\n", target->name, files.size());
  return 0;
}
