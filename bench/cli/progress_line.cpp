#include "bench/cli/progress_line.hpp"

#include <cstdio>

#include "harness/core/path_text.hpp"

namespace vsgl::cli {

void ProgressLine::show(const std::string& where, const TimingProgress& p) {
  if (!terminal_) return;  // the progress line is for people watching a terminal
  if (p.rounds == 0)
    std::fprintf(stderr, "\r  %s: warm-up %u/%u        ", where.c_str(), p.warmup_done, p.warmup_total);
  else
    std::fprintf(stderr, "\r  %s: repetition %u (min %u), worst IQR/median %.3f (target %.3f), %.1f s / %.0f s   ",
                 where.c_str(), p.rounds, p.min_rounds, p.worst_noise < 0 ? 0.0 : p.worst_noise, p.noise_target,
                 p.elapsed_s, p.cap_s);
  std::fflush(stderr);
  open_ = true;
}

void ProgressLine::message(const std::string& text) {
  close();
  std::fprintf(stderr, "%s\n", text.c_str());
}

void ProgressLine::close() {
  if (open_) std::fputc('\n', stderr);
  open_ = false;
}

void print_outcome(const std::vector<std::string>& markdown, const std::vector<std::filesystem::path>& written) {
  for (const auto& md : markdown) std::printf("%s\n", md.c_str());
  std::fflush(stdout);
  for (const auto& path : written) std::fprintf(stderr, "wrote %s\n", path_text(path).c_str());
}

}  // namespace vsgl::cli
