#pragma once
// Test helper: the layout GL gives a block's members in a linked program (program introspection),
// for checking C++ mirrors of GLSL structs against the driver's own offsets and strides. A member
// added, removed, resized or reordered on one side only changes an offset, a stride or the name set.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace nimbus::gpu::test {

struct MemberOffset {
    std::string name;
    std::size_t offset;
};

// One integer property of a named program resource; −1 where GL knows no such resource.
inline GLint resourceProperty(GLuint program, GLenum interface, const std::string& name, GLenum property) {
    const GLuint index = glGetProgramResourceIndex(program, interface, name.c_str());
    if (index == GL_INVALID_INDEX) return -1;
    GLint value = -1;
    glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
    return value;
}

// GL_OFFSET of an active uniform or buffer variable (`interface` GL_UNIFORM or GL_BUFFER_VARIABLE); −1 if inactive.
inline GLint resourceOffset(GLuint program, GLenum interface, const std::string& name) {
    return resourceProperty(program, interface, name, GL_OFFSET);
}

// The names of active variables of `interface` starting with `prefix`, with the prefix removed.
inline std::vector<std::string> activeMembers(GLuint program, GLenum interface, const std::string& prefix) {
    GLint count = 0;
    glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
    std::vector<std::string> names;
    for (GLint i = 0; i < count; ++i) {
        char name[256] = {};
        glGetProgramResourceName(program, interface, static_cast<GLuint>(i), sizeof name, nullptr, name);
        const std::string n = name;
        if (n.rfind(prefix, 0) == 0) names.push_back(n.substr(prefix.size()));
    }
    return names;
}

// Every member listed is at its C++ offset under `prefix` (e.g. "lights[0]." or "Frame."), and
// GL knows no member the list leaves out.
inline void expectMembers(GLuint program, GLenum interface, const std::string& prefix, const std::vector<MemberOffset>& members) {
    std::map<std::string, std::size_t> expected;
    for (const MemberOffset& m : members) {
        expected[m.name] = m.offset;
        EXPECT_EQ(resourceOffset(program, interface, prefix + m.name), static_cast<GLint>(m.offset)) << prefix << m.name;
    }
    const std::vector<std::string> active = activeMembers(program, interface, prefix);
    EXPECT_EQ(active.size(), members.size()) << prefix << ": GL and C++ list different members";
    for (const std::string& name : active) EXPECT_TRUE(expected.count(name)) << prefix << name << " has no C++ twin";
}

// The size GL gives a uniform or shader storage block (`interface` GL_UNIFORM_BLOCK or GL_SHADER_STORAGE_BLOCK).
inline GLint blockSize(GLuint program, GLenum interface, const std::string& block) {
    return resourceProperty(program, interface, block, GL_BUFFER_DATA_SIZE);
}

// The stride of an unsized (or top-level) array of structs in a shader storage block, read at one member.
inline GLint topLevelArrayStride(GLuint program, const std::string& member) {
    return resourceProperty(program, GL_BUFFER_VARIABLE, member, GL_TOP_LEVEL_ARRAY_STRIDE);
}

}  // namespace nimbus::gpu::test
