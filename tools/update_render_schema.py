#!/usr/bin/env python3
"""Writes the render block of docs/scene-format.schema.json from `sandbox settings --schema`.

Usage: tools/update_render_schema.py [path/to/sandbox]   (default build/release/bin/sandbox)
The declarations in the code are the source; sandbox_cli_test checks the file matches them. Only
the text of "$defs"/"render" is replaced, so the rest of the file keeps its hand formatting.
"""
import json
import os
import subprocess
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sandbox = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "release", "bin", "sandbox")
schema_path = os.path.join(root, "docs", "scene-format.schema.json")
render = json.loads(subprocess.run([sandbox, "settings", "--schema"], check=True, capture_output=True, text=True).stdout)

text = open(schema_path).read()
key = '\n    "render": {'
start = text.index(key) + 1
i, depth, in_string = text.index("{", start), 0, False
while True:  # the block's closing brace, skipping braces inside strings
    c = text[i]
    if in_string:
        if c == "\\":
            i += 1
        elif c == '"':
            in_string = False
    elif c == '"':
        in_string = True
    elif c == "{":
        depth += 1
    elif c == "}":
        depth -= 1
        if depth == 0:
            break
    i += 1
block = json.dumps(render, indent=2, ensure_ascii=False).replace("\n", "\n    ")
text = text[:start] + '    "render": ' + block + text[i + 1:]
json.loads(text)  # still one valid document
open(schema_path, "w").write(text)
print("wrote the render block of", schema_path)
