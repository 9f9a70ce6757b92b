#pragma once
// How the C allocator hands memory back to the operating system, tuned for a renderer.
//
// Why: Mesa's software rasterizer (llvmpipe) allocates its per-draw vertex buffers and binned
// scenes on the heap and frees them at the end of every frame. With glibc's defaults the freed
// top of the heap (anything over 128 KiB) goes back to the kernel, and the next frame faults
// every page in again. Measured on the dragon at 800x800 (docs/performance.md): ~3,000 page
// faults per frame, and a frame that re-draws both mesh passes took 95-99 ms instead of 65-69.
// Keeping freed memory in the process costs only its peak (about 12 MiB of RSS here).
namespace marble {

// Blocks from this size up are served by mmap (and returned at once when freed), smaller ones
// by the heap. 32 MiB is the largest glibc accepts on 64-bit (its dynamic threshold's ceiling).
inline constexpr int kMmapThresholdBytes = 32 << 20;
// Free memory at the top of the heap kept for reuse before any is returned to the kernel.
inline constexpr int kTrimThresholdBytes = 512 << 20;

// Applies both thresholds (glibc mallopt). Call once at start-up, before creating a GL context.
// Returns false when the allocator does not take them (another C library, or a sanitizer's
// allocator); nothing else changes then.
bool keepFreedMemoryForReuse();

}  // namespace marble
