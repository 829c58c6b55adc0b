#!/usr/bin/env node
/* rotorcert vectors adapter for ganja.js (https://github.com/enkimute/ganja.js), pinned 1.0.204.
 *
 *   node ganja_adapter.js --vectors DIR --out RESULTS.json     run every binary64 vector of the mapped ops
 *   node ganja_adapter.js --self-test                          check the hexfloat reader/printer
 *
 * ganja.js is found by plain require('ganja.js') (NODE_PATH or a node_modules next to this file).
 * It runs through ganja's object API, never the inline translator:
 *   C3  = Algebra({p: 3, baseType: Float64Array})        Cl(3,0): rotors (rotation ops)
 *   PGA = Algebra({p: 3, r: 1, baseType: Float64Array})  Cl(3,0,1): motors (dual-quaternion ops)
 * Float64Array is ganja's documented option for binary64 (README: "R3_64"); the default Algebra(3)
 * stores coefficients in a Float32Array, which would round every result to binary32.
 *
 * Conventions (spec Q2R-1, ALG-7, MOTOR-1), written with ganja's basis names: C3's bivectors are
 * e12, e13, e23 (no e31; e31 = -e13), PGA's are e01, e02, e03, e12, e13, e23 and e0123.
 *   quaternion [x, y, z, w]  <-> rotor  w - x e23 - y e31 - z e12  = s:w, e23:-x, e13:+y, e12:-z
 *   bivector [b23, b31, b12] <-> b23 e23 + b31 e31 + b12 e12       = e23:b23, e13:-b31, e12:b12
 *   log / exp vector v       <-> the bivector Phi(0, v) = -I v      = e23:-vx, e13:+vy, e12:-vz
 *   trivector a              <-> a e123
 *   dual quaternion [r, d]   <-> motor  w_r - x_r e23 - y_r e31 - z_r e12 - x_d e01 - y_d e02 - z_d e03 - w_d e0123
 *   point (x, y, z)          <-> x e032 + y e013 + z e021 + e123, built as ganja's own point,
 *                                !(e0 + x e1 + y e2 + z e3) (.Dual of a PGA vector), and read back as
 *                                (e032, e013, e021) / e123 (MOTOR-2: division by the e123 weight).
 *
 * The ABI ops and the ganja calls they are (every other ABI op is declared unsupported):
 *   normalize        r2q( Phi(q).Normalized )
 *   compose          r2q( Phi(a).Mul(Phi(b)) )                                 (b applied first)
 *   inverse          r2q( Phi(q).Inverse )
 *   apply_vector     C3.sw(Phi(q), v)          ganja's sandwich R x ~R (the >>> operator)
 *   apply_bivector   C3.sw(Phi(q), B)
 *   apply_trivector  C3.sw(Phi(q), a e123)
 *   to_matrix        C3.sw(Phi(q).Normalized, [e1, e2, e3]): column c = image of e_c (sw maps over arrays)
 *   from_axis_angle  r2q( axis.Normalized.Dual.Scale(-angle/2).Exp() ) = exp(-I u angle/2)  (Dual = times e123 in C3)
 *   log              Phi(q).Log()  read as the vector v of Phi(0, v)
 *   exp              Phi(0, v).Exp()
 *   (log_exp_round_trip: exp of what log returned, DOMAIN_ERROR when log's output is all NaN)
 *   dq_from_rotation_translation  PGA: T.Mul(Phi(q).Normalized), T = Bivector(-t/2 on e01, e02, e03).Exp() = 1 - t e0/2
 *   dq_compose       PGA: M(a).Mul(M(b))
 *   dq_apply_point   PGA.sw(M(d), P(p))
 *   dq_normalize     PGA: M(d).Normalized  (ganja's closed form M (M ~M)^(-1/2))
 * Rule: where ganja has a call for the op, it is called on the mapped input as it is (ganja's
 * sandwich, Log, Inverse, Mul assume nothing and check nothing; what they do with a non-unit, zero or
 * non-finite input is graded). Where ganja has no single call (to_matrix, from_axis_angle,
 * dq_from_rotation_translation) the spec's definition is written as one expression of ganja calls,
 * normalising with ganja's Normalized exactly where the definition normalises. No hemisphere flips,
 * no domain checks, no rescaling of our own: slerp, nlerp, blends and ScLERP need an adapter-written
 * hemisphere rule and are declared unsupported (adapter.json says why for every op).
 *
 * Status (RESULT-2, the rules of conformance/adapters/common/rcvectors.py): ganja has no status
 * channel; an exception thrown by ganja -> DOMAIN_ERROR with every output NaN; every output
 * component NaN -> DOMAIN_ERROR; anything else -> OK with the outputs as computed. A ReferenceError
 * or TypeError is a defect of this adapter and stops the run.
 *
 * Numbers: inputs are read from the vectors' "hex" strings with an exact hexfloat parser (BigInt,
 * round to nearest even) and written back as Python's float.hex() writes them, so the results file
 * is the same, byte for byte, as the shared Python runner would write for the same values.
 */
'use strict';

const fs = require('fs');
const path = require('path');

// ---- hexfloat <-> binary64, exact -------------------------------------------------------------

const scratch = new DataView(new ArrayBuffer(8));
const MANT_MASK = (1n << 52n) - 1n;

function bitsOf(x) { scratch.setFloat64(0, x); return scratch.getBigUint64(0); }
function fromBits(b) { scratch.setBigUint64(0, b); return scratch.getFloat64(0); }

/** A finite binary64, NaN or infinity as rcvectors.hexfloat writes it (Python float.hex()):
 *  0x1.<13 hex digits>p<exp> for normal numbers, 0x0.<13>p-1022 for subnormals, 0x0.0p+0 for zero. */
function hexfloat(x) {
  if (Number.isNaN(x)) return 'nan';
  if (x === Infinity) return 'inf';
  if (x === -Infinity) return '-inf';
  const b = bitsOf(x);
  const sign = b >> 63n ? '-' : '';
  const field = Number((b >> 52n) & 0x7ffn), mant = b & MANT_MASK;
  if (field === 0 && mant === 0n) return sign + '0x0.0p+0';
  const digits = mant.toString(16).padStart(13, '0');
  if (field === 0) return sign + '0x0.' + digits + 'p-1022';
  const e = field - 1023;
  return sign + '0x1.' + digits + 'p' + (e < 0 ? '-' : '+') + Math.abs(e);
}

const HEX_RE = /^([+-]?)(?:0[xX])?([0-9a-fA-F]*)(?:\.([0-9a-fA-F]*))?(?:[pP]([+-]?[0-9]+))?$/;

/** The binary64 nearest (ties to even) to a C99 / Python hexfloat string: sign, hex digits with an
 *  optional point, optional binary exponent. Exact: the significand is a BigInt. */
function parseHexfloat(s) {
  const m = HEX_RE.exec(s.trim());
  if (!m || (m[2] + (m[3] || '')).length === 0) throw new Error('not a hexfloat: ' + JSON.stringify(s));
  const neg = m[1] === '-', frac = m[3] || '';
  const sig = BigInt('0x' + m[2] + frac);          // value = sig * 2^e
  const e = (m[4] ? parseInt(m[4], 10) : 0) - 4 * frac.length;
  const signed = (x) => (neg ? -x : x);
  if (sig === 0n) return signed(0);
  const top = sig.toString(2).length - 1 + e;      // floor(log2 value)
  if (top > 1023) return signed(Infinity);
  if (top < -1076) return signed(0);               // below half the smallest subnormal
  const lsb = Math.max(top - 52, -1074);           // exponent of the last significand bit kept
  const shift = e - lsb;
  let q;
  if (shift >= 0) {
    q = sig << BigInt(shift);
  } else {
    const drop = BigInt(-shift), rest = sig & ((1n << drop) - 1n), half = 1n << (drop - 1n);
    q = sig >> drop;
    if (rest > half || (rest === half && (q & 1n))) q += 1n;
  }
  // value = q 2^lsb with q < 2^53: these bits are the biased encoding, including the carry of a
  // rounding into the next binade and the subnormal range (lsb = -1074).
  const bits = (BigInt(lsb + 1074) << 52n) + q;
  if (bits >= 0x7ffn << 52n) return signed(Infinity);
  return signed(fromBits(bits));
}

function decodeValue(h) {
  if (h === 'nan' || h === '-nan') return NaN;
  if (h === 'inf') return Infinity;
  if (h === '-inf') return -Infinity;
  return parseHexfloat(h);
}

// ---- ganja ----------------------------------------------------------------------------------

const Algebra = require('ganja.js');
const GANJA_VERSION = require('ganja.js/package.json').version;
const C3 = Algebra({p: 3, baseType: Float64Array});
const PGA = Algebra({p: 3, r: 1, baseType: Float64Array});

/** Q2R-1 into C3: w - x e23 - y e31 - z e12 (e31 = -e13). */
function rotor(q) {
  const R = new C3();
  R.s = q[3]; R.e23 = -q[0]; R.e13 = q[1]; R.e12 = -q[2];
  return R;
}
/** The inverse of Q2R-1 on the even part: [x, y, z, w] = [-R_e23, -R_e31, -R_e12, R_s]. */
function quat(R) { return [-R.e23, R.e13, -R.e12, R.s]; }

/** [e23, e31, e12] coefficients <-> a C3 bivector. */
function bivector(b) {
  const B = new C3();
  B.e23 = b[0]; B.e13 = -b[1]; B.e12 = b[2];
  return B;
}
function bivectorCoeffs(B) { return [B.e23, -B.e13, B.e12]; }

/** The quaternion-view vector v <-> the bivector Phi(0, v) = -(vx e23 + vy e31 + vz e12). */
function logBivector(v) { return bivector([-v[0], -v[1], -v[2]]); }
function logVector(B) { const b = bivectorCoeffs(B); return [-b[0], -b[1], -b[2]]; }

/** MOTOR-1 into PGA. */
function motor(d) {
  const M = new PGA();
  M.s = d[3]; M.e23 = -d[0]; M.e13 = d[1]; M.e12 = -d[2];
  M.e01 = -d[4]; M.e02 = -d[5]; M.e03 = -d[6]; M.e0123 = -d[7];
  return M;
}
function dualQuat(M) { return [-M.e23, M.e13, -M.e12, M.s, -M.e01, -M.e02, -M.e03, -M.e0123]; }
/** The rotor of q embedded in PGA (Q2R-1). */
function pgaRotor(q) { return motor([q[0], q[1], q[2], q[3], 0, 0, 0, 0]); }

/** ALG-7 point x e032 + y e013 + z e021 + e123, built as ganja's point !(e0 + x e1 + y e2 + z e3). */
function point(p) { return PGA.Vector(1, p[0], p[1], p[2]).Dual; }
/** (e032, e013, e021) / e123, with e032 = -e023 and e021 = -e012. */
function pointCoords(P) { const w = P.e123; return [-P.e023 / w, P.e013 / w, -P.e012 / w]; }

const OPS = {
  normalize: (q) => quat(rotor(q).Normalized),
  compose: (a, b) => quat(rotor(a).Mul(rotor(b))),
  inverse: (q) => quat(rotor(q).Inverse),
  apply_vector: (q, v) => { const r = C3.sw(rotor(q), C3.Vector(v[0], v[1], v[2])); return [r.e1, r.e2, r.e3]; },
  apply_bivector: (q, b) => bivectorCoeffs(C3.sw(rotor(q), bivector(b))),
  apply_trivector: (q, a) => { const X = new C3(); X.e123 = a; return C3.sw(rotor(q), X).e123; },
  to_matrix: (q) => {
    const columns = C3.sw(rotor(q).Normalized, [C3.Vector(1, 0, 0), C3.Vector(0, 1, 0), C3.Vector(0, 0, 1)]);
    return columns.flatMap((c) => [c.e1, c.e2, c.e3]);  // column-major: m[c*3 + r]
  },
  from_axis_angle: (angle, axis) =>
    quat(C3.Vector(axis[0], axis[1], axis[2]).Normalized.Dual.Scale(-angle / 2).Exp()),
  log: (q) => logVector(rotor(q).Log()),
  exp: (v) => quat(logBivector(v).Exp()),
  dq_from_rotation_translation: (q, t) => {
    const T = PGA.Bivector(-t[0] / 2, -t[1] / 2, -t[2] / 2, 0, 0, 0).Exp();  // e01, e02, e03 first
    return dualQuat(T.Mul(pgaRotor(q).Normalized));
  },
  dq_compose: (a, b) => dualQuat(motor(a).Mul(motor(b))),
  dq_apply_point: (d, p) => pointCoords(PGA.sw(motor(d), point(p))),
  dq_normalize: (d) => dualQuat(motor(d).Normalized),
};

// ---- vectors and results (the rules of conformance/adapters/common/rcvectors.py) ----------------

// Output arrays of each ABI op, in the order the op writes them, and their strides (impl_abi.h).
const OUTPUTS = {
  normalize: [['out_q', 4]], compose: [['out_q', 4]], inverse: [['out_q', 4]],
  apply_vector: [['out_v', 3]], apply_bivector: [['out_b', 3]], apply_trivector: [['out_s', 1]],
  to_matrix: [['out_m', 9]], from_matrix: [['out_q', 4]],
  to_axis_angle: [['out_angle', 1], ['out_axis', 3]], from_axis_angle: [['out_q', 4]],
  log: [['out_v', 3]], exp: [['out_q', 4]], slerp: [['out_q', 4]], nlerp: [['out_q', 4]],
  blend_qlb: [['out_q', 4]], blend_log: [['out_q', 4]],
  dq_from_rotation_translation: [['out_d', 8]], dq_compose: [['out_d', 8]],
  dq_apply_point: [['out_p', 3]], dq_normalize: [['out_d', 8]], dq_sclerp: [['out_d', 8]],
  dq_blend: [['out_d', 8]], rotate_about_axis: [['out_p', 3]],
  skin_linear: [['out_v', 3]], skin_dual_quaternion: [['out_v', 3]],
  log_exp_round_trip: [['out_q', 4]],
};

/** EXP-2: exp of what log returned; DOMAIN_ERROR (a thrown error) when log's output is all NaN. */
function roundTrip(log, exp) {
  return (q) => {
    const v = log(q);
    if (v.every((c) => Number.isNaN(c))) throw new RangeError('log refused the input');
    return exp(v);
  };
}

function decode(arr, stride, perInfluence, k) {
  const values = arr.hex.map(decodeValue);
  if (perInfluence) {
    const out = [];
    for (let i = 0; i < k; i++) out.push(stride > 1 ? values.slice(i * stride, (i + 1) * stride) : values[i]);
    return out;
  }
  return stride > 1 ? values : values[0];
}

function flatten(v) {
  if (typeof v === 'number') return [v];
  return Array.from(v, Number);
}

/** [status, {output name: numbers}, why] of one call under the status rule. */
function call(op, fn, inputs) {
  const outs = OUTPUTS[op];
  let arrays;
  try {
    let result = fn(...inputs);
    if (outs.length === 1) result = [result];
    arrays = {};
    outs.forEach(([name, stride], i) => {
      arrays[name] = flatten(result[i]);
      if (arrays[name].length !== stride)
        throw new RangeError(`${name}: ${arrays[name].length} values, expected ${stride}`);
    });
  } catch (e) {
    if (e instanceof ReferenceError || e instanceof TypeError) throw e;  // the adapter's defect
    const nan = {};
    for (const [name, stride] of outs) nan[name] = new Array(stride).fill(NaN);
    return ['DOMAIN_ERROR', nan, e.constructor.name];
  }
  const all = Object.values(arrays).flat();
  if (all.every((x) => Number.isNaN(x))) return ['DOMAIN_ERROR', arrays, null];
  return ['OK', arrays, null];
}

function runVectors(vectorsDir, ops, numberFormat) {
  const index = JSON.parse(fs.readFileSync(path.join(vectorsDir, 'index.json'), 'utf8'));
  const results = [], refused = {};
  for (const entry of index.files) {
    if (entry.number_format !== numberFormat || !(entry.op in ops)) continue;
    const vf = JSON.parse(fs.readFileSync(path.join(vectorsDir, entry.file), 'utf8'));
    const fn = ops[vf.op];
    const layout = vf.inputs.map((a) => [a.name, a.stride, Boolean(a.per_influence)]);
    for (const test of vf.tests) {
      const inputs = layout.map(([name, stride, per]) => decode(test.in[name], stride, per, test.k));
      const [status, out, why] = call(vf.op, fn, inputs);
      if (why) refused[vf.op] = (refused[vf.op] || 0) + 1;
      const hexOut = {};
      for (const [name, values] of Object.entries(out)) hexOut[name] = values.map(hexfloat);
      results.push({id: test.id, status, out: hexOut});
    }
  }
  return [results, refused];
}

/** JSON as Python's json.dumps writes it without indent (", " and ": "), for one result per line. */
function pyJson(v) {
  if (Array.isArray(v)) return '[' + v.map(pyJson).join(', ') + ']';
  if (v !== null && typeof v === 'object')
    return '{' + Object.keys(v).map((k) => JSON.stringify(k) + ': ' + pyJson(v[k])).join(', ') + '}';
  return JSON.stringify(v);
}

/** The results file (format rotorcert-results 1), written atomically, one result per line. */
function writeResults(file, vectorsDir, implementation, results, unsupported) {
  const outDir = path.dirname(path.resolve(file));
  const head = {
    format: 'rotorcert-results',
    format_version: 1,
    implementation,
    vectors: path.relative(outDir, path.resolve(vectorsDir)) || '.',
    unsupported_ops: [...unsupported].sort(),
    results: null,
  };
  let text = JSON.stringify(head, null, 2);
  const body = results.map(pyJson).join(',\n    ');
  text = text.replace('"results": null', results.length ? '"results": [\n    ' + body + '\n  ]' : '"results": []');
  const tmp = file + '.tmp';
  fs.writeFileSync(tmp, text + '\n');
  fs.renameSync(tmp, file);
}

const IMPLEMENTATION = {
  name: 'ganja',
  version: GANJA_VERSION,
  scalar: 'double',
  description:
    'ganja.js ' + GANJA_VERSION + ' object API, Algebra({p:3,baseType:Float64Array}) rotors and ' +
    'Algebra({p:3,r:1,baseType:Float64Array}) motors (MOTOR-1), through the JSON-vectors adapter ' +
    'conformance/adapters/ganja; status rule: an exception thrown by ganja -> DOMAIN_ERROR with NaN ' +
    'outputs, every output NaN -> DOMAIN_ERROR (RESULT-2, ganja has no status channel), otherwise OK',
};

// ---- self-test of the number conversions ----------------------------------------------------

function selfTest() {
  let failures = 0;
  const same = (a, b) => bitsOf(a) === bitsOf(b) || (Number.isNaN(a) && Number.isNaN(b));
  const expect = (what, got, want) => {
    const ok = typeof want === 'number' ? same(got, want) : got === want;
    if (!ok) { failures++; console.log(`FAIL ${what}: got ${String(got)} (${typeof got === 'number' ? hexfloat(got) : ''}), want ${String(want)}`); }
  };
  const MIN_SUB = fromBits(1n), MAX_SUB = fromBits((1n << 52n) - 1n), MIN_NORM = fromBits(1n << 52n);
  // Printer: Python float.hex() spellings.
  expect('hex 1', hexfloat(1), '0x1.0000000000000p+0');
  expect('hex -0', hexfloat(-0), '-0x0.0p+0');
  expect('hex +0', hexfloat(0), '0x0.0p+0');
  expect('hex min subnormal', hexfloat(MIN_SUB), '0x0.0000000000001p-1022');
  expect('hex max subnormal', hexfloat(MAX_SUB), '0x0.fffffffffffffp-1022');
  expect('hex min normal', hexfloat(MIN_NORM), '0x1.0000000000000p-1022');
  expect('hex max', hexfloat(Number.MAX_VALUE), '0x1.fffffffffffffp+1023');
  expect('hex 0.1', hexfloat(0.1), '0x1.999999999999ap-4');
  expect('hex -pi', hexfloat(-Math.PI), '-0x1.921fb54442d18p+1');
  expect('hex nan/inf', [NaN, Infinity, -Infinity].map(hexfloat).join(' '), 'nan inf -inf');
  // Parser: C99 %a spellings of the exporter, Python spellings, and rounding to nearest even.
  const cases = [
    ['0x0p+0', 0], ['-0x0p+0', -0], ['0x1p+0', 1], ['-0x1.8p+1', -3], ['0x1p-1074', MIN_SUB],
    ['-0x1p-1074', -MIN_SUB], ['0x0.0000000000001p-1022', MIN_SUB], ['0x1.ffffffffffffep-1023', MAX_SUB],
    ['0x1p-1022', MIN_NORM], ['0x1.fffffffffffffp+1023', Number.MAX_VALUE], ['0x1p+1023', 2 ** 1023],
    ['0x1p+1024', Infinity], ['-0x1p+1024', -Infinity], ['0x1.fffffffffffff8p+1023', Infinity],
    ['0x1.fffffffffffff7p+1023', Number.MAX_VALUE],
    ['0x1.00000000000008p+0', 1], ['0x1.00000000000018p+0', 1 + 2 ** -51],
    ['0x1.000000000000080001p+0', 1 + 2 ** -52], ['0x1.00000000000007ffp+0', 1],
    ['0x0.8p-1074', 0], ['0x0.8000001p-1074', MIN_SUB], ['0x1.8p-1074', 2 * MIN_SUB], ['0x1p-1076', 0],
    ['0x1.fffffffffffff8p-1023', MIN_NORM], ['0x3p-1075', 2 * MIN_SUB],
    ['0x1.921fb54442d18p+1', Math.PI], ['0x.8p1', 1], ['0x10p-4', 1], ['1p0', 1],
  ];
  for (const [s, want] of cases) expect('parse ' + s, parseHexfloat(s), want);
  for (const bad of ['', '0x', 'p3', '0x1q3', '0x1.2.3p0']) {
    let threw = false;
    try { parseHexfloat(bad); } catch (e) { threw = true; }
    if (!threw) { failures++; console.log('FAIL parse accepted ' + JSON.stringify(bad)); }
  }
  // Round trip of every kind of bit pattern: parse(hex(x)) is x, bit for bit (-0 included).
  const special = [0, -0, 1, -1, MIN_SUB, -MIN_SUB, MAX_SUB, MIN_NORM, Number.MAX_VALUE, -Number.MAX_VALUE,
                   2 ** 1023, 2 ** -1023, 3 * MIN_SUB, 0.1, Math.PI, 1e300, -(2 ** -1060)];
  let seed = 0x9e3779b97f4a7c15n;
  const next = () => { seed ^= seed << 13n; seed &= (1n << 64n) - 1n; seed ^= seed >> 7n; seed ^= seed << 17n; seed &= (1n << 64n) - 1n; return seed; };
  const pool = special.slice();
  for (let i = 0; i < 20000; i++) {
    let b = next();
    if (i % 4 === 1) b &= (1n << 63n) | MANT_MASK;            // subnormals and zeros
    if (i % 4 === 2) b |= 0x7fen << 52n;                      // huge
    const x = fromBits(b);
    if (Number.isFinite(x)) pool.push(x);
  }
  let roundTrips = 0;
  for (const x of pool) {
    const y = parseHexfloat(hexfloat(x));
    if (!same(x, y)) { failures++; if (failures < 20) console.log(`FAIL round trip ${hexfloat(x)} -> ${hexfloat(y)}`); }
    roundTrips++;
  }
  console.log(`self-test: ${cases.length} parse cases, ${roundTrips} round trips, ${failures} failures`);
  return failures ? 1 : 0;
}

// ---- command line -----------------------------------------------------------------------------

function usage(msg) {
  if (msg) console.error('ganja_adapter.js: ' + msg);
  console.error('usage: node ganja_adapter.js --vectors DIR --out RESULTS.json | --self-test');
  return 2;
}

function main(argv) {
  const args = {};
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--self-test') args.selfTest = true;
    else if (a === '--vectors' || a === '--out') { if (i + 1 >= argv.length) return usage(a + ' needs a value'); args[a.slice(2)] = argv[++i]; }
    else if (a.startsWith('--vectors=') || a.startsWith('--out=')) { const j = a.indexOf('='); args[a.slice(2, j)] = a.slice(j + 1); }
    else if (a === '-h' || a === '--help') { usage(); return 0; }
    else return usage('unknown argument ' + a);
  }
  if (args.selfTest) return selfTest();
  if (!args.vectors || !args.out) return usage('--vectors and --out are required');
  const ops = Object.assign({}, OPS, {log_exp_round_trip: roundTrip(OPS.log, OPS.exp)});
  const [results, refused] = runVectors(args.vectors, ops, 'binary64');
  const unsupported = Object.keys(OUTPUTS).filter((op) => !(op in ops) && op !== 'log_exp_round_trip');
  writeResults(args.out, args.vectors, IMPLEMENTATION, results, unsupported);
  const note = Object.keys(refused).sort().map((op) => `${op} ${refused[op]}`).join(', ');
  console.log(`ganja: wrote ${results.length} results to ${args.out}` +
              (note ? ` (exceptions, graded as DOMAIN_ERROR: ${note})` : ''));
  return 0;
}

if (require.main === module) process.exitCode = main(process.argv.slice(2));

module.exports = {hexfloat, parseHexfloat, OPS};
