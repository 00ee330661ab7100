#pragma once
// Float transcendentals that give the same bits with every C library (DESIGN.md §13.1): glibc's
// tanf and mingw-w64's differ in the last bit for some arguments, which changed the camera
// projection, hence P and the BRSM PDF of a capture recorded on Windows. Evaluated in double and
// rounded once to float, the result is the correctly rounded float unless the double lands within
// a double's error of a halfway point between two floats, which no library differs on in practice.
#include <cmath>

namespace vsgl::portable {

inline float tan(float x) { return static_cast<float>(std::tan(static_cast<double>(x))); }
inline float sin(float x) { return static_cast<float>(std::sin(static_cast<double>(x))); }
inline float cos(float x) { return static_cast<float>(std::cos(static_cast<double>(x))); }
inline float pow(float x, float y) {
  return static_cast<float>(std::pow(static_cast<double>(x), static_cast<double>(y)));
}

}  // namespace vsgl::portable
