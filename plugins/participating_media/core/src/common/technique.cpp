// The technique table's bookkeeping (nimbus/media/technique.h): names once, keys once.
#include "nimbus/media/technique.h"

#include <algorithm>
#include <stdexcept>

#include "nimbus/base/error.h"

namespace nimbus::media {

void TechniqueTable::add(TechniqueEntry entry) {
    if (find(entry.name) != nullptr) throw std::logic_error("media mode '" + entry.name + "' registered twice");
    for (SettingSpec& spec : entry.settings) {
        for (const TechniqueEntry& other : entries_)
            for (const SettingSpec& theirs : other.settings)
                if (theirs.key == spec.key)
                    throw std::logic_error("setting '" + spec.key + "' declared by modes " + other.name + " and " + entry.name);
        spec.modes = {entry.name};
    }
    entries_.push_back(std::move(entry));
}

const TechniqueEntry* TechniqueTable::find(const std::string& name) const {
    const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const TechniqueEntry& e) { return e.name == name; });
    return it == entries_.end() ? nullptr : &*it;
}

std::vector<std::string> TechniqueTable::names() const {
    std::vector<std::string> out;
    for (const TechniqueEntry& e : entries_) out.push_back(e.name);
    return out;
}

const TechniqueEntry& TechniqueTable::at(const std::string& name, const std::string& origin) const {
    if (entries_.empty()) throw std::logic_error("an empty media technique table");
    if (name.empty()) return entries_.front();
    if (const TechniqueEntry* entry = find(name)) return *entry;
    std::string known;
    for (const TechniqueEntry& e : entries_) known += (known.empty() ? "" : ", ") + e.name;
    throwInputError(origin, name, "", "unknown media mode (known: " + known + ")");
}

}  // namespace nimbus::media
