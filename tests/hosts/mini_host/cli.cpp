#include "cli.h"

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

namespace mini {
namespace {

bool parseInt(std::string_view text, int& out) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size();
}

void parseSize(const std::string& text, Options& o) {
    const auto x = text.find('x');
    if (x == std::string::npos || !parseInt(std::string_view(text).substr(0, x), o.width) ||
        !parseInt(std::string_view(text).substr(x + 1), o.height) || o.width < 1 || o.height < 1 || o.width > 16384 || o.height > 16384)
        throw UsageError("--size: expected WxH with each side in 1..16384, not \"" + text + "\"");
}

void parseTime(const std::string& text, Options& o) {
    std::size_t used = 0;
    try {
        o.time = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || used == 0 || !std::isfinite(o.time) || o.time < 0.0)
        throw UsageError("--time: expected a finite number of seconds ≥ 0, not \"" + text + "\"");
}

void requireExr(const std::filesystem::path& file, const char* option) {
    if (file.extension() != ".exr") throw UsageError(std::string(option) + ": mini_host writes EXR only (\"" + file.string() + "\")");
}


void parseMediaScale(const std::string& text, Options& o) {
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || used == 0 || !(value >= 0.0625 && value <= 1.0))
        throw UsageError("--media-scale: expected a number in [0.0625, 1], not \"" + text + "\"");
    o.mediaScale = static_cast<float>(value);
}

}  // namespace

const char* usage() {
    return "usage: mini_host SCENE.gltf --out F.exr [--size WxH] [--time T] [--media-out M.exr] [--mode particles|blocks|raymarch|sheets|billboards] "
           "[--media-scale S] [--quality exact|balanced|fast] [--depth reversed|standard]";
}

Options parseArguments(int argc, const char* const* argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help") {
            o.help = true;
            return o;
        }
        const bool takesValue = arg == "--out" || arg == "--size" || arg == "--time" || arg == "--media-out" || arg == "--mode" ||
                                arg == "--media-scale" || arg == "--depth" || arg == "--quality";
        if (takesValue && i + 1 >= argc) throw UsageError(arg + ": missing value");
        if (arg == "--out") o.out = argv[++i];
        else if (arg == "--media-out") o.mediaOut = argv[++i];
        else if (arg == "--size") parseSize(argv[++i], o);
        else if (arg == "--time") parseTime(argv[++i], o);
        else if (arg == "--mode") o.mode = argv[++i];
        else if (arg == "--media-scale") parseMediaScale(argv[++i], o);
        else if (arg == "--quality") {
            o.quality = argv[++i];
            if (o.quality != "exact" && o.quality != "balanced" && o.quality != "fast")
                throw UsageError("--quality: expected exact, balanced or fast, not \"" + o.quality + "\"");
        }
        else if (arg == "--depth") {
            const std::string depth = argv[++i];
            if (depth != "reversed" && depth != "standard") throw UsageError("--depth: expected reversed or standard, not \"" + depth + "\"");
            o.standardDepth = depth == "standard";
        }
        else if (arg.rfind("-", 0) == 0) throw UsageError("unknown option " + arg);
        else if (o.scene.empty()) o.scene = arg;
        else throw UsageError("one scene only (got \"" + o.scene.string() + "\" and \"" + arg + "\")");
    }
    if (o.scene.empty()) throw UsageError("no scene given");
    if (o.out.empty()) throw UsageError("--out is required");
    requireExr(o.out, "--out");
    if (!o.mediaOut.empty()) requireExr(o.mediaOut, "--media-out");
    return o;
}

}  // namespace mini
