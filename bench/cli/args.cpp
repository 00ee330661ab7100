#include "bench/cli/args.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "harness/core/error.hpp"

namespace vsgl::cli {

Args::Args(int argc, char** argv, int first) {
  for (int i = first; i < argc; ++i) tokens_.emplace_back(argv[i]);
  used_.assign(tokens_.size(), false);
}

bool Args::flag(const std::string& name) {
  bool found = false;
  for (std::size_t i = 0; i < tokens_.size(); ++i)
    if (!used_[i] && tokens_[i] == name) used_[i] = found = true;
  return found;
}

std::optional<std::string> Args::value(const std::string& name) {
  std::optional<std::string> out;
  for (std::size_t i = 0; i < tokens_.size(); ++i) {
    if (used_[i]) continue;
    if (tokens_[i] == name) {
      if (i + 1 >= tokens_.size()) throw UsageError(name + " needs a value");
      used_[i] = used_[i + 1] = true;
      out = tokens_[i + 1];
      ++i;
    } else if (tokens_[i].rfind(name + "=", 0) == 0) {
      used_[i] = true;
      out = tokens_[i].substr(name.size() + 1);
    }
  }
  return out;
}

std::vector<std::string> Args::values(const std::string& name) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < tokens_.size(); ++i) {
    if (used_[i]) continue;
    if (tokens_[i] == name) {
      if (i + 1 >= tokens_.size()) throw UsageError(name + " needs a value");
      used_[i] = used_[i + 1] = true;
      out.push_back(tokens_[i + 1]);
      ++i;
    } else if (tokens_[i].rfind(name + "=", 0) == 0) {
      used_[i] = true;
      out.push_back(tokens_[i].substr(name.size() + 1));
    }
  }
  return out;
}

std::string Args::string(const std::string& name, const std::string& fallback) {
  return value(name).value_or(fallback);
}

std::vector<std::string> Args::list(const std::string& name, const std::string& fallback) {
  std::vector<std::string> out;
  std::stringstream ss(string(name, fallback));
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

namespace {
uint32_t parse_u32(const std::string& name, const std::string& text) {
  uint32_t v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size() || text.empty())
    throw UsageError(name + " takes a non-negative whole number, not '" + text + "'");
  return v;
}
}  // namespace

uint32_t Args::u32(const std::string& name, uint32_t fallback, uint32_t min_value) {
  const auto v = value(name);
  if (!v) return fallback;
  const uint32_t n = parse_u32(name, *v);
  if (n < min_value) throw UsageError(name + " must be at least " + std::to_string(min_value) + ", not " + *v);
  return n;
}

float Args::positive_float(const std::string& name, float fallback) {
  const auto v = value(name);
  if (!v) return fallback;
  std::size_t used = 0;
  float f = 0.0f;
  try {
    f = std::stof(*v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != v->size() || !std::isfinite(f)) throw UsageError(name + " takes a number, not '" + *v + "'");
  if (f <= 0.0f) throw UsageError(name + " must be positive, not " + *v);
  return f;
}

std::pair<uint32_t, uint32_t> Args::size(const std::string& name, std::pair<uint32_t, uint32_t> fallback) {
  const auto v = value(name);
  if (!v) return fallback;
  const auto x = v->find('x');
  if (x == std::string::npos) throw UsageError(name + " takes WIDTHxHEIGHT (e.g. 1920x1088), not '" + *v + "'");
  const uint32_t w = parse_u32(name, v->substr(0, x));
  const uint32_t h = parse_u32(name, v->substr(x + 1));
  if (w == 0 || h == 0) throw UsageError(name + " must be at least 1x1, not " + *v);
  return {w, h};
}

void Args::finish() const {
  for (std::size_t i = 0; i < tokens_.size(); ++i)
    if (!used_[i]) throw UsageError("unknown argument '" + tokens_[i] + "'");
}

}  // namespace vsgl::cli
