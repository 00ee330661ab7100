#pragma once
// Errors a user can cause (bad input, bad options, unusable device). The CLI prints what() and
// exits with the code; nothing else of a run is written once one is thrown.
#include <stdexcept>
#include <string>

namespace vsgl {

enum class ExitCode : int {
  kOk = 0,
  kFailure = 1,         // a check failed (verify, a compare --fail-on verdict)
  kUsage = 2,           // bad command line
  kBadInput = 3,        // missing / corrupt / inconsistent capture or parameter
  kDevice = 4,          // no usable device, no timestamps, device lost, out of memory
  kValidation = 5,      // the Khronos validation layer reported errors
  kInternal = 70,       // an unexpected exception: a bug (EX_SOFTWARE of sysexits.h)
};

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A size the device cannot hold (a storage-buffer range, an image side, an allocation): the device
// itself is fine, so a sweep records the point as beyond the device and goes on (DESIGN.md §10.1).
class DeviceLimitError : public DeviceError {
 public:
  using DeviceError::DeviceError;
};

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace vsgl
