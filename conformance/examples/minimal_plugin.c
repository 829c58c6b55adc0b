/* A complete rotorcert plugin in plain C: the worked example of conformance/CERTIFY.md.
 *
 * It stands for "your library": one binary64 table with two operations, normalize (NORM-1) and
 * compose (COMPOSE-1), over the ABI's batched arrays (impl_abi.h: quaternions [x, y, z, w]).
 * Build and certify it:
 *
 *   cc -std=c11 -O2 -fPIC -shared -I impls/include conformance/examples/minimal_plugin.c -o minimal.so -lm
 *   build/default/conformance/rotorcert certify --plugin ./minimal.so --out cert
 *
 * The ctest conformance_example_plugin builds and certifies it on every run, so this file stays
 * what the guide says it is. Define MINIMAL_PLUGIN_BUG to compose b a instead of a b: COMPOSE-1
 * then FAILs and the certificate names the convention the failure is consistent with.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include <rotorcert/impl_abi.h>

/* A quaternion that describes a rotation: finite and not zero (EDGE-6, EDGE-7). */
static int is_rotation(const double* q) {
  int nonzero = 0;
  for (int i = 0; i < 4; ++i) {
    if (!isfinite(q[i])) return 0;
    nonzero |= q[i] != 0.0;
  }
  return nonzero;
}

static void domain_error(double* out, size_t stride, uint8_t* status) {
  for (size_t i = 0; i < stride; ++i) out[i] = NAN;
  *status = RC_DOMAIN_ERROR;
}

/* q / |q|, scaled by a power of two first so that |q|^2 neither overflows nor underflows (EDGE-5). */
static int normalize(size_t n, const double* q, double* out_q, uint8_t* status) {
  for (size_t e = 0; e < n; ++e, q += 4, out_q += 4) {
    if (!is_rotation(q)) {
      domain_error(out_q, 4, status + e);
      continue;
    }
    double m = 0;
    for (int i = 0; i < 4; ++i) m = fmax(m, fabs(q[i]));
    int k;
    frexp(m, &k);
    double s[4], sum = 0;
    for (int i = 0; i < 4; ++i) {
      s[i] = ldexp(q[i], -k);
      sum += s[i] * s[i];
    }
    const double norm = sqrt(sum);
    for (int i = 0; i < 4; ++i) out_q[i] = s[i] / norm;
    status[e] = RC_OK;
  }
  return 0;
}

/* The Hamilton product a b: b is applied first (COMPOSE-1). */
static int compose(size_t n, const double* a, const double* b, double* out_q, uint8_t* status) {
  for (size_t e = 0; e < n; ++e, a += 4, b += 4, out_q += 4) {
    if (!is_rotation(a) || !is_rotation(b)) {
      domain_error(out_q, 4, status + e);
      continue;
    }
#ifdef MINIMAL_PLUGIN_BUG
    const double* t = a;
    a = b;
    b = t;
#endif
    const double ax = a[0], ay = a[1], az = a[2], aw = a[3], bx = b[0], by = b[1], bz = b[2], bw = b[3];
    out_q[0] = aw * bx + ax * bw + ay * bz - az * by;
    out_q[1] = aw * by - ax * bz + ay * bw + az * bx;
    out_q[2] = aw * bz + ax * by - ay * bx + az * bw;
    out_q[3] = aw * bw - ax * bx - ay * by - az * bz;
#ifdef MINIMAL_PLUGIN_BUG
    b = a;
    a = t;
#endif
    status[e] = RC_OK;
  }
  return 0;
}

/* Every other operation NULL: NOT_SUPPORTED. */
static const rc_ops_f64 ops = {.normalize = normalize, .compose = compose};
static const char* const clauses[] = {"NORM-1", "COMPOSE-1", NULL};
static const rc_impl table = {
    .abi_version = RC_ABI_VERSION,
    .name = "minimal",
    .version = "1.0",
    .description = "the worked example of CERTIFY.md: normalize and compose in C",
    .scalar = RC_SCALAR_FLOAT64,
    .levels = RC_LEVEL_CORE,
    .clauses = clauses,
    .f64 = &ops,
};

__attribute__((visibility("default"))) const rc_impl* rotorcert_impl_entry(uint32_t abi_version, uint32_t index) {
  return abi_version == RC_ABI_VERSION && index == 0 ? &table : NULL;
}
