#pragma once
// Code shared by the CPU and the GPU, written once (pbrt-v4's PBRT_CPU_GPU): a function marked
// HIKARI_HD compiles for both when nvcc builds the file (core/device_launch.h launches it), and is
// an ordinary function everywhere else. Mark only what compiles for the device: no std::vector,
// no exceptions, no virtual calls, no host-only library calls inside (flat arrays through
// core/flat_view.h instead). constexpr functions need no mark (--expt-relaxed-constexpr).

#if defined(__CUDACC__)
#define HIKARI_HD __host__ __device__
#else
#define HIKARI_HD
#endif

/// True while nvcc compiles the device side of a file (an `#if` for the few places where the
/// GPU needs its own spelling of the same operation, e.g. a bit cast).
#if defined(__CUDA_ARCH__)
#define HIKARI_DEVICE_PASS 1
#else
#define HIKARI_DEVICE_PASS 0
#endif
