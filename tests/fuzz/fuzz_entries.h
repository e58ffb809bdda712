#pragma once
// What the fuzz targets feed untrusted bytes to, each the same path a user's input takes. Every
// entry accepts the input or refuses it with an InputError, which it swallows: anything else (an
// exception of another type, a crash, a leak, undefined behaviour) is a bug the fuzzer reports.
// libfuzzer_main.cpp turns each into a libFuzzer target (the asan preset builds them);
// replay_test.cpp feeds them every file of the seed and regression corpora in every build.
//
// Does not: render (no GL), write files, or read any file but the content scene a target starts from.
#include <cstddef>
#include <cstdint>

namespace nimbus::fuzz {

// A .gltf (JSON) or .glb file from memory, through what `sandbox validate` runs: the loader's
// checks, the media extension, the render block, the emitters simulated to kSceneTime, and the
// validate report. Relative URIs name a folder that does not exist, so the bytes are all there is.
inline constexpr double kSceneTime = 0.25;
void loadScene(const std::uint8_t* data, std::size_t size);

// An editor script (sandbox/editor/script.h) run headless against content/scenes/smoke.gltf,
// stopping at the first refused line as `sandbox edit --script` does. `open` and `save` are
// skipped (no files), and so are `time` and `play` beyond kScriptTimeLimit seconds: a long
// simulation is allowed, and only slow.
inline constexpr double kScriptTimeLimit = 10.0;
void runEditorScript(const std::uint8_t* data, std::size_t size);

// Settings as a user types them, read by a session over content/scenes/smoke.gltf: lines of
// KEY=VALUE (--set), "--mode M" and "--quality Q", then, from the first line that starts with
// '{', a render block for the scene's medium (docs/scene-format.md §3.5).
void readSettings(const std::uint8_t* data, std::size_t size);

}  // namespace nimbus::fuzz
