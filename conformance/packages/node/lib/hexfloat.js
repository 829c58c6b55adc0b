'use strict';
/* Exact number text of the vector and results files (conformance/VECTORS.md): an exact hexfloat
 * parser (BigInt significand, round to nearest even) and a printer that writes what Python's
 * float.hex() writes, so that a results file is the same, byte for byte, whichever of the two
 * packages wrote it. */

const scratch = new DataView(new ArrayBuffer(8));
const MANT_MASK = (1n << 52n) - 1n;

function bitsOf(x) { scratch.setFloat64(0, x); return scratch.getBigUint64(0); }
function fromBits(b) { scratch.setBigUint64(0, b); return scratch.getFloat64(0); }

/** A finite binary64, NaN or infinity as Python's float.hex() (rotorcert_vectors.hexfloat) writes it:
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

/** The value of a vector's "hex" string: a hexfloat, or nan, -nan, inf, -inf. */
function decodeValue(h) {
  if (h === 'nan' || h === '-nan') return NaN;
  if (h === 'inf') return Infinity;
  if (h === '-inf') return -Infinity;
  return parseHexfloat(h);
}

/** The printer and parser on fixed spellings (Python float.hex(), C99 %a of the exporter, ties of
 *  rounding, subnormals, -0, overflow) and parse(hexfloat(x)) === x, bit for bit, on 20000
 *  pseudo-random bit patterns; returns {parseCases, roundTrips, failures: [message]}. */
function checkHexfloat() {
  const failures = [];
  const same = (a, b) => bitsOf(a) === bitsOf(b) || (Number.isNaN(a) && Number.isNaN(b));
  const expect = (what, got, want) => {
    const ok = typeof want === 'number' ? same(got, want) : got === want;
    if (!ok) failures.push(`${what}: got ${String(got)} (${typeof got === 'number' ? hexfloat(got) : ''}), want ${String(want)}`);
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
    if (!threw) failures.push('parse accepted ' + JSON.stringify(bad));
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
    if (!same(x, y)) failures.push(`round trip ${hexfloat(x)} -> ${hexfloat(y)}`);
    roundTrips++;
  }
  return {parseCases: cases.length, roundTrips, failures};
}

module.exports = {hexfloat, parseHexfloat, decodeValue, bitsOf, fromBits, checkHexfloat};
