#include "io/temp_file_cleanup.h"

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>

#include <unistd.h>

namespace prism {
namespace {

// Fixed storage: the handler may only read memory that nothing allocates or frees under it.
constexpr size_t kSlots = 16;
constexpr size_t kPathBytes = 4096;
constexpr int kFree = 0, kFilling = 1, kWatched = 2;

struct Slot {
    std::atomic<int> state{kFree};
    char path[kPathBytes];
};
std::array<Slot, kSlots> slots;
std::once_flag handlersInstalled;

extern "C" void removeTempFilesAndStop(int signal) {
    for (Slot &slot : slots)
        if (slot.state.load() == kWatched)
            ::unlink(slot.path); // async-signal-safe
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

void installHandlers() {
    for (int signal : {SIGTERM, SIGINT, SIGHUP}) {
        struct sigaction old {};
        if (::sigaction(signal, nullptr, &old) != 0 || old.sa_handler != SIG_DFL)
            continue;
        struct sigaction action {};
        action.sa_handler = removeTempFilesAndStop;
        sigemptyset(&action.sa_mask);
        ::sigaction(signal, &action, nullptr);
    }
}

} // namespace

int watchTempFile(const std::filesystem::path &path) {
    std::call_once(handlersInstalled, installHandlers);
    std::string text = std::filesystem::absolute(path).string();
    if (text.size() >= kPathBytes)
        return -1;
    for (size_t i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (slots[i].state.compare_exchange_strong(expected, kFilling)) {
            std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
            slots[i].state.store(kWatched);
            return int(i);
        }
    }
    return -1;
}

void unwatchTempFile(int slot) {
    if (slot >= 0 && size_t(slot) < kSlots)
        slots[size_t(slot)].state.store(kFree);
}

} // namespace prism
