#version 450 core
#include "main.frag"
