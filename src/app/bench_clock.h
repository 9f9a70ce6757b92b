#pragma once
// The clocks a frame is measured with. Wall clock for what the user waits; CPU clocks to
// tell our own submission cost from the driver's (on llvmpipe the "GPU" is other threads).
namespace marble {

double wallMs();           // monotonic (steady) clock
double threadCpuMs();      // CPU time of the calling thread
double processCpuMs();     // CPU time of every thread of the process

}  // namespace marble
