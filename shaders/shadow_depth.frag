#version 450 core
// Depth comes from the rasteriser; nothing to shade.
void main() {}
