#version 450 core
#include "a.glsl"
