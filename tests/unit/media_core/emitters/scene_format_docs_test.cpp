// Tests that docs/scene-format.md and docs/scene-format.schema.json agree with the code: every
// emitter example in the documentation parses, the schema is valid JSON naming exactly the keys and
// presets the parser accepts.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "nimbus/media/emitter_desc.h"

namespace nimbus::media {
namespace {

using Json = nlohmann::json;

std::string readText(const std::string& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in) << "cannot open " << path;
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The bodies of the fenced blocks opened by exactly "```json emitter".
std::vector<std::string> emitterExamples(const std::string& markdown) {
    std::vector<std::string> blocks;
    std::istringstream lines(markdown);
    std::string line, body;
    bool inside = false;
    while (std::getline(lines, line)) {
        if (!inside && line == "```json emitter") {
            inside = true;
            body.clear();
        } else if (inside && line == "```") {
            inside = false;
            blocks.push_back(body);
        } else if (inside) {
            body += line + "\n";
        }
    }
    EXPECT_FALSE(inside) << "unterminated block";
    return blocks;
}

Json schema() { return Json::parse(readText(NIMBUS_DOCS_DIR "/scene-format.schema.json")); }

TEST(SceneFormatDocs, EveryEmitterExampleParses) {
    const std::vector<std::string> examples = emitterExamples(readText(NIMBUS_DOCS_DIR "/scene-format.md"));
    ASSERT_GE(examples.size(), 3u);
    const ParseContext where{"docs/scene-format.md", -1, "example"};
    for (const std::string& text : examples) {
        SCOPED_TRACE(text);
        EXPECT_NO_THROW(parseEmitter(Json::parse(text), where));
    }
}

TEST(SceneFormatDocs, SchemaIsDraft2020JsonWithRootAndNode) {
    const Json s = schema();
    EXPECT_EQ(s.at("$schema"), "https://json-schema.org/draft/2020-12/schema");
    for (const char* def : {"root", "node", "medium", "particles", "emitter", "render", "volume", "noise", "generator"})
        EXPECT_TRUE(s.at("$defs").contains(def)) << def;
    EXPECT_EQ(s["$defs"]["node"]["required"], Json::array({"medium"}));
    std::set<std::string> nodeKeys;
    for (const auto& [key, value] : s["$defs"]["node"]["properties"].items()) nodeKeys.insert(key);
    EXPECT_EQ(nodeKeys, (std::set<std::string>{"medium", "particles", "emitter", "render", "volume", "generator"}));
    // Every "$ref" points at a definition that exists.
    std::vector<const Json*> stack{&s};
    int refs = 0;
    while (!stack.empty()) {
        const Json* j = stack.back();
        stack.pop_back();
        if (j->is_object()) {
            if (j->contains("$ref")) {
                const std::string ref = (*j)["$ref"];
                ASSERT_EQ(ref.rfind("#/$defs/", 0), 0u) << ref;
                EXPECT_TRUE(s["$defs"].contains(ref.substr(8))) << ref;
                ++refs;
            }
            for (const auto& [key, value] : j->items()) stack.push_back(&value);
        } else if (j->is_array()) {
            for (const Json& value : *j) stack.push_back(&value);
        }
    }
    EXPECT_GT(refs, 10);
}

TEST(SceneFormatDocs, SchemaListsExactlyTheEmitterKeysAndPresetsTheParserAccepts) {
    const Json emitter = schema()["$defs"]["emitter"];
    EXPECT_EQ(emitter["additionalProperties"], false);
    std::set<std::string> schemaKeys, parserKeys;
    for (const auto& [key, value] : emitter["properties"].items()) schemaKeys.insert(key);
    for (std::string_view key : kEmitterKeys) parserKeys.insert(std::string(key));
    EXPECT_EQ(schemaKeys, parserKeys);

    std::set<std::string> schemaPresets, parserPresets;
    for (const Json& name : emitter["properties"]["preset"]["enum"]) schemaPresets.insert(name.get<std::string>());
    for (EmitterPreset p : kEmitterPresets) parserPresets.insert(std::string(presetName(p)));
    EXPECT_EQ(schemaPresets, parserPresets);

    // The bounds the parser enforces are the schema's.
    EXPECT_EQ(emitter["properties"]["max_particles"]["maximum"].get<std::uint32_t>(), kMaxEmitterParticles);
    EXPECT_EQ(emitter["properties"]["rate"]["maximum"].get<double>(), kMaxEmitterRate);
    EXPECT_EQ(emitter["properties"]["bursts"]["maxItems"].get<std::size_t>(), kMaxEmitterBursts);
}

TEST(SceneFormatDocs, TheDocumentNamesEveryKeyAndPreset) {
    const std::string doc = readText(NIMBUS_DOCS_DIR "/scene-format.md");
    // Built with append: GCC 12 warns falsely (-Wrestrict) on chained operator+ of short strings.
    const auto quoted = [](std::string_view name, std::string_view before, std::string_view after) {
        std::string s(before);
        s.append(name).append(after);
        return s;
    };
    for (std::string_view key : kEmitterKeys) EXPECT_NE(doc.find(quoted(key, "| `", "` |")), std::string::npos) << key;
    for (EmitterPreset p : kEmitterPresets) EXPECT_NE(doc.find(quoted(presetName(p), "`", "`")), std::string::npos);
    for (const char* convention : {"3 lux", "normalize(−0.4, −1.0, −0.3)", "--camera NAME", "--size", "clamp(1 − (d/range)⁴, 0, 1)²",
                                   "no tone curve"})
        EXPECT_NE(doc.find(convention), std::string::npos) << convention;
}

}  // namespace
}  // namespace nimbus::media
