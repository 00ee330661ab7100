// Measures whether the capture loader should call OpenEXR's checkOpenEXRFile (ImfCheckFile.h)
// before reading an EXR: its cost on a full-size view, and what it catches that
// harness/exr_io.cpp read_exr does not, over a corpus of fuzzed capture inputs.
// Usage: measure_check_file [CORPUS_DIR...]   (inputs as fuzz_capture reads them)
#include <OpenEXR/ImfCheckFile.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_input_files.hpp"
#include "harness/core/error.hpp"
#include "harness/capture/exr_io.hpp"

namespace {

double seconds_of(const std::function<void()>& f, int repeats) {
  double best = 1e30;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const vsgl::fuzz::ScratchDir scratch;
  // A full-size G-buffer view: 1920x1088, 15 float channels, like a recorded capture.
  const uint32_t w = 1920, h = 1088;
  std::vector<std::vector<float>> planes(15, std::vector<float>(std::size_t{w} * h));
  uint32_t state = 1;
  for (auto& p : planes)
    for (auto& v : p) {
      state = state * 1664525u + 1013904223u;
      v = static_cast<float>(state >> 8) / 16777216.0f;
    }
  std::vector<vsgl::ExrChannelToWrite> channels;
  for (int c = 0; c < 15; ++c) channels.push_back({"c" + std::to_string(10 + c), planes[c]});
  const auto file = scratch.path() / "view.exr";
  vsgl::write_exr(file, w, h, channels);
  const double read_s = seconds_of([&] { (void)vsgl::read_exr(file); }, 3);
  const double check_s = seconds_of([&] { (void)Imf::checkOpenEXRFile(file.c_str(), false, false, false); }, 3);
  const double check_reduced_s = seconds_of([&] { (void)Imf::checkOpenEXRFile(file.c_str(), true, true, false); }, 3);
  std::printf("full-size view %ux%u x15 float, %.1f MB: read_exr %.3f s, checkOpenEXRFile %.3f s, "
              "checkOpenEXRFile(reduceMemory, reduceTime) %.3f s\n",
              w, h, static_cast<double>(std::filesystem::file_size(file)) / 1e6, read_s, check_s, check_reduced_s);

  int files = 0, read_rejects = 0, check_flags = 0, flagged_but_read = 0, read_but_flagged_reduced = 0;
  for (int a = 1; a < argc; ++a) {
    for (const auto& entry : std::filesystem::directory_iterator(argv[a])) {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string input((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      const auto parts = vsgl::fuzz::split_parts(input, 3);
      for (std::size_t i = 0; i < parts.size() && i < 2; ++i) {
        const auto exr = scratch.write("part.exr", parts[i]);
        ++files;
        bool read_ok = true;
        try {
          (void)vsgl::read_exr(exr, [](uint32_t pw, uint32_t ph) {
            if (uint64_t{pw} * ph > (uint64_t{1} << 25)) throw vsgl::InputError("too large");
          });
        } catch (const vsgl::InputError&) {
          read_ok = false;
          ++read_rejects;
        }
        const bool flagged = Imf::checkOpenEXRFile(exr.c_str(), true, true, false);
        check_flags += flagged ? 1 : 0;
        if (flagged && read_ok) ++flagged_but_read;
        if (!flagged && !read_ok) ++read_but_flagged_reduced;
      }
    }
  }
  if (files > 0)
    std::printf("corpus: %d EXR parts; read_exr rejects %d; checkOpenEXRFile(reduced) flags %d; flagged but "
                "read_exr reads all pixels: %d; read_exr rejects but check passes: %d\n",
                files, read_rejects, check_flags, flagged_but_read, read_but_flagged_reduced);
  return 0;
}
