#include "recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "nimbus/base/log.h"

namespace nimbus::sandbox::editor {
namespace {

constexpr std::size_t kMaxFiles = 10;

std::filesystem::path storePath() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "nimbus" / "recent-files";
    if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".config" / "nimbus" / "recent-files";
    return {};
}

}  // namespace

RecentFiles::RecentFiles() : store_(storePath()) {
    std::ifstream in(store_);
    for (std::string line; std::getline(in, line) && files_.size() < kMaxFiles;)
        if (!line.empty()) files_.push_back(line);
}

void RecentFiles::add(const std::filesystem::path& file) {
    std::error_code ec;
    const std::string path = std::filesystem::absolute(file, ec).lexically_normal().string();
    std::vector<std::string> next;
    next.reserve(kMaxFiles);
    next.push_back(path);
    for (const std::string& f : files_)
        if (f != path && next.size() < kMaxFiles) next.push_back(f);
    files_ = std::move(next);
    if (store_.empty()) return;
    std::filesystem::create_directories(store_.parent_path(), ec);
    std::ofstream out(store_, std::ios::trunc);
    for (const std::string& f : files_) out << f << '\n';
    if (!out) log::warn("editor: cannot write the recent-files list " + store_.string());
}

}  // namespace nimbus::sandbox::editor
