#pragma once
// The editor's recent-files list, kept in $XDG_CONFIG_HOME/nimbus/recent-files (or
// ~/.config/nimbus/recent-files), newest first, one absolute path per line.
//
// Does not: fail the editor when the list cannot be read or written (it is a convenience).
#include <filesystem>
#include <string>
#include <vector>

namespace nimbus::sandbox::editor {

class RecentFiles {
public:
    RecentFiles();  // reads the list
    const std::vector<std::string>& files() const { return files_; }
    void add(const std::filesystem::path& file);  // moves it to the front and writes the list

private:
    std::filesystem::path store_;
    std::vector<std::string> files_;
};

}  // namespace nimbus::sandbox::editor
