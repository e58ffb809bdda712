#pragma once
// Widgets that edit one JSON field of the document: they show the value, keep the user's half-typed
// or half-dragged value while the widget is active, and commit it once, when the widget is let go.
// A refused value stays on screen with the loader's message under the field until edited again.
//
// Does not: validate values (the loader does, through EditorState).
#include <map>
#include <optional>
#include <string>

#include "editor_state.h"

namespace nimbus::sandbox::editor {

class FieldWidgets {
public:
    explicit FieldWidgets(EditorState& state) : state_(&state) {}
    void rebind(EditorState& state) { state_ = &state; }

    // Each edits `path` on `node` (-1: the root object); `fallback` is shown when the field is absent.
    void number(const char* label, int node, const std::string& path, double fallback, float speed = 0.01f);
    void integer(const char* label, int node, const std::string& path, int fallback);
    void vector(const char* label, int node, const std::string& path, int components, const Json& fallback, float speed = 0.01f);
    void colour(const char* label, int node, const std::string& path, const Json& fallback, bool hdr);
    void choice(const char* label, int node, const std::string& path, const std::vector<std::string>& options,
                const std::string& fallback, bool allowNone = false);
    void text(const char* label, int node, const std::string& path);
    // Every field under `path` as a tree of the widgets above, whatever its schema.
    void tree(const char* label, int node, const std::string& path);

    // The last refusal, for the status bar; cleared when read.
    std::optional<std::string> takeError();
    // Sets the field as one undoable edit; a refusal is shown under the field.
    void commit(int node, const std::string& path, const Json& value);

private:
    void showError(int node, const std::string& path);
    void treeValue(const std::string& label, int node, const std::string& path, const Json& value);
    static std::string key(int node, const std::string& path);

    EditorState* state_;
    std::map<std::string, Json> editing_;  // values of active widgets, by key
    std::string errorKey_, errorText_;
    std::optional<std::string> pending_;
};

}  // namespace nimbus::sandbox::editor
