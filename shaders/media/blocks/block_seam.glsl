// The seam mask (block_seam_mask_pass.cpp): one texel per cell of `cell`² media texels, 1 where the
// opaque surface seen through one of them lies among a block's particles (a mesh inside the
// medium), else 0. block_seam_mask.frag writes it; block_composite.frag reads it to shade exactly
// (BLOCK_EXACT_SHADING) only there, where the smooth shading's error shows as a seam.

// The share of the media texel at `texel` (window coordinates of the media target) that takes the
// exact shading: 1 within the mask's cells and half a cell around them, falling to 0 over the next
// cell, so the smooth shading around the seam meets the exact one without a step. Cells grow with
// the image (blocks/block_seam_mask_pass.h seamMaskCell), so the ramp is as wide a share of the image at any size.
float seamWeight(sampler2D mask, vec2 texel, int cell) {
    ivec2 last = textureSize(mask, 0) - 1;
    vec2 p = texel / float(cell) - 0.5;  // cell i's centre is at (i + 0.5)·cell
    ivec2 base = ivec2(floor(p));
    vec2 f = p - vec2(base);
    // The mask widened by one cell (the maximum over 3×3) at the four cells around p, read from the
    // 4×4 cells around them.
    float cells[16];
    for (int k = 0; k < 16; ++k) cells[k] = texelFetch(mask, clamp(base + ivec2(k & 3, k >> 2) - 1, ivec2(0), last), 0).r;
    float widened[4];
    for (int j = 0; j < 4; ++j) {
        int x = j & 1, y = j >> 1;
        float m = 0.0;
        for (int k = 0; k < 9; ++k) m = max(m, cells[(y + k / 3) * 4 + x + k % 3]);
        widened[j] = m;
    }
    return mix(mix(widened[0], widened[1], f.x), mix(widened[2], widened[3], f.x), f.y);
}
