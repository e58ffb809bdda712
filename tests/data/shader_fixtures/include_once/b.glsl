  #  include "a.glsl"
float fromB;
