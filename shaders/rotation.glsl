// A ring of sample directions by rotation (a complex product) rather than a cosine and a sine per
// sample: llvmpipe evaluates those as polynomials per lane, and the bounce's gathers (bounce.glsl;
// until session 25 also the screen-space further bounces) took 112 of them per texel. Each direction is the previous one turned by
// a constant angle: the same directions to float rounding (under 1e-6 after 64 turns).
vec2 rotate2(vec2 v, vec2 by) { return vec2(v.x * by.x - v.y * by.y, v.x * by.y + v.y * by.x); }
