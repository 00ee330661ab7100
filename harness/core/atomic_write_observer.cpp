#include "harness/core/atomic_write_observer.hpp"

#include <atomic>

namespace vsgl {
namespace {

std::atomic<AtomicWriteObserver*> g_observer{nullptr};

}  // namespace

void set_atomic_write_observer(AtomicWriteObserver* observer) { g_observer.store(observer); }

AtomicWriteObserver* atomic_write_observer() { return g_observer.load(); }

}  // namespace vsgl
