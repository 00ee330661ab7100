#pragma once
// A device, build and run as a document records them (harness/formats/run_header.hpp), for tests
// that make documents without a device.
#include <string>

#include "harness/formats/run_header.hpp"

namespace vsgl::test {

inline DeviceRecord synthetic_device(const std::string& name = "synthetic", const std::string& type = "cpu") {
  DeviceRecord d;
  d.name = name;
  d.type = type;
  d.api_version = "1.3.0";
  d.driver_version = "1.0.0";
  d.driver_name = "test driver";
  d.queue_family = 0;
  d.graphics = true;
  d.timestamps = true;
  d.timestamp_valid_bits = 64;
  d.timestamp_period_ns = 1.0;
  d.usable = true;
  return d;
}

inline BuildRecord synthetic_build(const std::string& git_commit = "0123456789abcdef") {
  return {"0.1.0", git_commit, false, "test", false};
}

inline RunRecord synthetic_run(const std::string& started_utc = "2026-01-01T00:00:00Z", bool quick = true) {
  RunRecord r;
  r.started_utc = started_utc;
  r.quick = quick;
  return r;
}

}  // namespace vsgl::test
