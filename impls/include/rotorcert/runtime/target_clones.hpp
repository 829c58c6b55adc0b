// ROTORCERT_TARGET_CLONES: a batch function compiled twice, for AVX2 and for the x86-64 baseline
// (SSE2), the loader picking one by the CPU (GNU ifunc), as libraries with runtime dispatch do
// (rotor_simd does it with Highway). AVX2 holds eight floats or four doubles per vector where
// SSE2 holds four or two. Without FMA (not part of the "avx2" target; the sources that use this
// also build with -ffp-contract=off) both clones round every operation alike, so they return the
// same bits: the SIMD width changes the speed, never a result.
//
// `flatten` inlines the batch function's callees (the lane kernels, the batch driver) into each
// clone, so that the AVX2 clone's loops are compiled for AVX2 too, not called in their baseline
// version. Elsewhere, and under sanitizers (whose runtime does not expect ifuncs), one baseline
// version.
#pragma once

#if defined(__x86_64__) && defined(__ELF__) && (!defined(__clang__) || __clang_major__ >= 14) && \
    !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
#define ROTORCERT_TARGET_CLONES
#endif
#endif
#ifndef ROTORCERT_TARGET_CLONES
#define ROTORCERT_TARGET_CLONES __attribute__((target_clones("avx2", "default")))
#endif
#else
#define ROTORCERT_TARGET_CLONES
#endif

/// ROTORCERT_TARGET_CLONES with every callee inlined into each clone: GCC only. Clang 14 refuses
/// flatten beside target_clones, and clones without it would call the baseline kernels, so with
/// Clang these functions are compiled once, for the baseline.
#if defined(__GNUC__) && !defined(__clang__)
#define ROTORCERT_TARGET_CLONES_FLAT __attribute__((flatten)) ROTORCERT_TARGET_CLONES
#else
#define ROTORCERT_TARGET_CLONES_FLAT
#endif
