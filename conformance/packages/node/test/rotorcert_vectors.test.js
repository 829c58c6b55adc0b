'use strict';
/* Unit tests of rotorcert-vectors: the number texts, the status rule, the results file, the reader.
 * Run by ctest (conformance_package_node_test): `node --test conformance/packages/node/test/`. */

const assert = require('node:assert');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const {test} = require('node:test');
const rv = require('..');

// The results file both packages write for these entries (python: tests/test_rotorcert_vectors.py).
const GOLDEN = `{
  "format": "rotorcert-results",
  "format_version": 1,
  "implementation": {
    "name": "golden",
    "version": "1",
    "scalar": "double",
    "claimed_clauses": [
      "NORM-1"
    ],
    "preconditions": [
      "slerp:t_in_unit_interval"
    ],
    "hygiene": [
      "HYG-1"
    ]
  },
  "vectors": "vectors",
  "unsupported_ops": [
    "compose",
    "slerp"
  ],
  "results": [
    {"id": "NORM-1/normalize/binary64/0001", "status": "OK", "out": {"out_q": ["0x0.0p+0", "-0x0.0p+0", "0x0.0000000000001p-1022", "0x1.fffffffffffffp+1023"]}},
    {"id": "EDGE-6/normalize/binary64/0001", "status": "DOMAIN_ERROR", "out": {"out_q": ["nan", "nan", "inf", "-inf"]}},
    {"id": "EDGE-7/normalize/binary64/0001", "status": 255, "out": {"out_q": ["nan", "nan", "nan", "nan"]}}
  ]
}
`;

const UNIT = [[0, 0, 0, 1]];

test('hexfloat: fixed spellings, rounding ties and 20000 round trips', () => {
  const report = rv.checkHexfloat();
  assert.deepStrictEqual(report.failures, []);
  assert.ok(report.roundTrips > 10000);
});

test('status rule (RESULT-2)', () => {
  const cases = [
    [(q) => q, 'OK', null],
    [() => [NaN, NaN, NaN, NaN], 'DOMAIN_ERROR', null],
    [() => [NaN, 1, NaN, NaN], 'OK', null],
    [() => null, 'DOMAIN_ERROR', 'returned null'],
    [() => undefined, 'DOMAIN_ERROR', 'returned undefined'],
    [() => { throw new RangeError('not a rotation'); }, 'DOMAIN_ERROR', 'RangeError'],
    [() => new Float64Array([0, 0, 0, 1]), 'OK', null],
  ];
  for (const [fn, status, refusal] of cases) {
    const outcome = rv.call('normalize', fn, UNIT);
    assert.deepStrictEqual([outcome.status, outcome.refusal], [status, refusal], String(fn));
  }
  const hang = rv.call('normalize', () => { throw new rv.DidNotReturn('stopped'); }, UNIT);
  assert.strictEqual(hang.status, 255);
});

test('defects of the mapping are not refusals', () => {
  for (const fn of [() => undefinedName, (q) => q.no.such, () => [1, 2, 3]]) {  // eslint-disable-line no-undef
    assert.throws(() => rv.call('normalize', fn, UNIT), rv.AdapterError, String(fn));
  }
  assert.throws(() => rv.call('to_axis_angle', () => [0.5, 1, 0, 0], UNIT), rv.AdapterError);
  assert.deepStrictEqual(rv.call('to_axis_angle', () => [0.5, [1, 0, 0]], UNIT).outputs,
                         {out_angle: [0.5], out_axis: [1, 0, 0]});
});

test('round trip refuses when log does', () => {
  const refused = rv.roundTrip(() => [NaN, NaN, NaN], () => [0, 0, 0, 1]);
  assert.strictEqual(rv.call('log_exp_round_trip', refused, UNIT).status, 'DOMAIN_ERROR');
});

test('results file: the same text as the Python package writes', () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'rotorcert-vectors-'));
  try {
    fs.mkdirSync(path.join(dir, 'vectors'));
    const impl = new rv.Implementation({name: 'golden', version: '1', scalar: 'double', ops: {normalize: (q) => q},
                                        claimedClauses: ['NORM-1'], preconditions: ['slerp:t_in_unit_interval']});
    const entries = [
      new rv.Outcome('OK', {out_q: [0, -0, 5e-324, Number.MAX_VALUE]}).result('NORM-1/normalize/binary64/0001'),
      new rv.Outcome('DOMAIN_ERROR', {out_q: [NaN, NaN, Infinity, -Infinity]}).result('EDGE-6/normalize/binary64/0001'),
      new rv.Outcome(255, {out_q: [NaN, NaN, NaN, NaN]}).result('EDGE-7/normalize/binary64/0001'),
    ];
    const file = path.join(dir, 'results.json');
    rv.writeResults(file, path.join(dir, 'vectors'), impl, entries, ['slerp', 'compose']);
    assert.strictEqual(fs.readFileSync(file, 'utf8'), GOLDEN);
  } finally {
    fs.rmSync(dir, {recursive: true, force: true});
  }
});

test('implementation: unsupported ops, the derived round trip, unknown ops refused', () => {
  const id = (x) => x;
  const impl = new rv.Implementation({name: 'x', scalar: 'float', ops: {log: id, exp: id}});
  assert.strictEqual(impl.numberFormat, 'binary32');
  assert.ok('log_exp_round_trip' in impl.ops);
  assert.ok(impl.unsupportedOps.includes('normalize') && !impl.unsupportedOps.includes('log'));
  assert.throws(() => new rv.Implementation({name: 'x', scalar: 'double', ops: {normalise: id}}), TypeError);
});

test('reader: k elements per influence, and the vector named in a defect', () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'rotorcert-vectors-'));
  try {
    const vf = {format: 'rotorcert-vectors', format_version: 1, clause: 'QLB-1', op: 'blend_qlb',
                inputs: [{name: 'q', stride: 4, per_influence: true}, {name: 'w', stride: 1, per_influence: true}],
                tests: [{tcId: 1, id: 'QLB-1/blend_qlb/binary64/0001', comment: 'random', flags: ['Random'], k: 2,
                         in: {q: {hex: ['0x0p+0', '0x0p+0', '0x0p+0', '0x1p+0', '0x1p-1', '0x0p+0', '0x0p+0', '-0x1.8p+0']},
                              w: {hex: ['0x1p-1', 'nan']}},
                         expected: {status: 'OK'}, result: 'valid'}]};
    fs.writeFileSync(path.join(dir, 'QLB-1_blend_qlb_binary64.json'), JSON.stringify(vf));
    fs.writeFileSync(path.join(dir, 'index.json'), JSON.stringify({
      format: 'rotorcert-vectors-index', format_version: 1, files: [{file: 'QLB-1_blend_qlb_binary64.json', clause: 'QLB-1',
        level: 'Blend', op: 'blend_qlb', number_format: 'binary64', tolerance: 'eps32', numberOfTests: 1}]}));
    const vs = new rv.VectorSet(dir);
    assert.deepStrictEqual(vs.files('binary32'), []);
    const [vector] = vs.files('binary64')[0].vectors;
    const [q, w] = vector.arguments();
    assert.deepStrictEqual(q, [[0, 0, 0, 1], [0.5, 0, 0, -1.5]]);
    assert.ok(w[0] === 0.5 && Number.isNaN(w[1]));
    const impl = new rv.Implementation({name: 'x', scalar: 'double', ops: {blend_qlb: (qs) => qs[0].shape.length}});
    assert.throws(() => rv.run(impl, dir), /QLB-1\/blend_qlb\/binary64\/0001 \(random\): blend_qlb\(q=\[0x0p\+0/);
    fs.writeFileSync(path.join(dir, 'index.json'), '{"format": "something-else"}');
    assert.throws(() => new rv.VectorSet(dir), rv.VectorsError);
  } finally {
    fs.rmSync(dir, {recursive: true, force: true});
  }
});

test('a call that modifies its inputs is reported (HYG-1)', () => {
  const clean = rv.call('normalize', (q) => q.slice(), [[0, 0, 0, 2]]);
  assert.strictEqual(clean.modified, '');
  assert.ok(!('modified_inputs' in clean.result('NORM-1/normalize/binary64/0001')));
  const inPlace = rv.call('normalize', (q) => { q[3] = 1; return q; }, [[0, 0, 0, 2]]);
  assert.match(inPlace.modified, /input arrays/);
  class Box { constructor(v) { this.v = Array.from(v); } }
  const viaObject = rv.call('normalize', (q) => { const b = rv.watch(new Box(q)); b.v[0] = -0; return [0, 0, 0, 1]; }, [[0, 0, 0, 1]]);
  assert.match(viaObject.result('NORM-1/normalize/binary64/0001').modified_inputs, /watched input object 0 \(Box\)/);
});
