#include "nimbus/base/log.h"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace nimbus::log {
namespace {
std::atomic<Level> g_level{Level::Warn};
std::mutex g_write;
}  // namespace

void setLevel(Level l) { g_level.store(l); }
Level level() { return g_level.load(); }

void write(Level l, std::string_view message) {
    if (l < g_level.load()) return;
    static constexpr const char* kTag[] = {"debug", "info", "warning", "error", ""};
    std::lock_guard lock(g_write);
    std::fprintf(stderr, "nimbus %s: %.*s\n", kTag[static_cast<int>(l)], static_cast<int>(message.size()),
                 message.data());
}

}  // namespace nimbus::log
