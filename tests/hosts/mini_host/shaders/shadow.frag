#version 450 core
// Depth comes from the rasteriser.
void main() {}
