#version 450 core
// comment
void main() {}
