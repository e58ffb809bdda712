#version 450 core
out vec4 c;
void main() {
    c = vec4(1.0) +;
}
