'use strict';
/* What is certified (Implementation) and the results file (format rotorcert-results, version 1,
 * conformance/VECTORS.md) that `rotorcert vectors check` grades. */

const fs = require('fs');
const path = require('path');
const {ABI_OPS, NUMBER_FORMATS, OUTPUTS, ROUND_TRIP} = require('./abi');
const {roundTrip} = require('./outcome');

const HEADER_KEYS = ['name', 'version', 'scalar', 'description', 'claimed_clauses', 'claimed_levels',
                     'preconditions', 'conventions'];

/** A library to certify: the results file's `implementation` object and one function per ABI op.
 *
 *  new Implementation({name, scalar, ops, version, description, claimedClauses, claimedLevels,
 *                      preconditions, conventions})
 *
 *  name, scalar ('float' or 'double': the binary32 or the binary64 vectors) and ops ({ABI op name:
 *  function}) are required. claimedClauses / claimedLevels: what is certified (default: every
 *  clause with a result / the levels of the claimed clauses). preconditions / conventions
 *  (DECL-1): 'op:id' strings of what the library documents, e.g. 'slerp:t_in_unit_interval'.
 *  With log and exp and no function of its own for log_exp_round_trip, EXP-2's round trip is exp
 *  of what log returned. Every ABI op without a function is declared unsupported (RESULT-1). */
class Implementation {
  constructor(spec) {
    const {name, scalar, ops} = spec;
    if (typeof name !== 'string' || name === '') throw new TypeError('Implementation: name must be a non-empty string');
    if (!(scalar in NUMBER_FORMATS)) throw new TypeError(`Implementation: scalar must be 'float' or 'double', not ${scalar}`);
    if (ops === null || typeof ops !== 'object') throw new TypeError('Implementation: ops must be an object {op: function}');
    const unknown = Object.keys(ops).filter((op) => !(op in OUTPUTS)).sort();
    if (unknown.length) throw new TypeError(`not ABI ops (impls/include/rotorcert/impl_abi.h): ${unknown.join(', ')}`);
    this.name = name;
    this.scalar = scalar;
    this.version = spec.version;
    this.description = spec.description;
    this.ops = Object.assign({}, ops);
    if (!(ROUND_TRIP in this.ops) && this.ops.log && this.ops.exp) this.ops[ROUND_TRIP] = roundTrip(this.ops.log, this.ops.exp);
    this.claimedClauses = spec.claimedClauses || spec.claimed_clauses;
    this.claimedLevels = spec.claimedLevels || spec.claimed_levels;
    this.preconditions = spec.preconditions || [];
    this.conventions = spec.conventions || [];
  }

  /** From a results file's implementation object ({name, version, scalar, description, ...}) and
   *  ops; keys this class does not know are kept, in their order. */
  static fromObject(implementation, ops) {
    const impl = new Implementation(Object.assign({}, implementation, {ops}));
    impl._extra = {};
    for (const [k, v] of Object.entries(implementation)) if (!HEADER_KEYS.includes(k)) impl._extra[k] = v;
    return impl;
  }

  get numberFormat() { return NUMBER_FORMATS[this.scalar]; }

  get unsupportedOps() { return ABI_OPS.filter((op) => !(op in this.ops)).sort(); }

  /** The results file's `implementation` object (only the fields that are set). */
  header() {
    const h = {name: this.name};
    if (this.version !== undefined) h.version = this.version;
    h.scalar = this.scalar;
    if (this.description !== undefined) h.description = this.description;
    if (this.claimedClauses) h.claimed_clauses = [...this.claimedClauses];
    if (this.claimedLevels) h.claimed_levels = [...this.claimedLevels];
    if (this.preconditions.length) h.preconditions = [...this.preconditions];
    if (this.conventions.length) h.conventions = [...this.conventions];
    h.hygiene = ['HYG-1'];  // every call is checked for modified inputs (outcome.watch)
    return Object.assign(h, this._extra || {});
  }
}

/** JSON as Python's json.dumps writes it without indent (', ' and ': '), for one result per line. */
function pyJson(v) {
  if (Array.isArray(v)) return '[' + v.map(pyJson).join(', ') + ']';
  if (v !== null && typeof v === 'object')
    return '{' + Object.keys(v).map((k) => JSON.stringify(k) + ': ' + pyJson(v[k])).join(', ') + '}';
  return JSON.stringify(v);
}

/** The text of a results file, as the Python package writes it: `implementation` (an object or an
 *  Implementation), `results` (entries, Outcome.result), `unsupported` (ABI op names); `vectors`
 *  relative to the results file; one result per line. */
function resultsText(resultsPath, vectorsDir, implementation, results, unsupported) {
  const outDir = path.dirname(path.resolve(resultsPath));
  const head = {
    format: 'rotorcert-results',
    format_version: 1,
    implementation: implementation instanceof Implementation ? implementation.header() : implementation,
    vectors: path.relative(outDir, path.resolve(vectorsDir)) || '.',
    unsupported_ops: [...unsupported].sort(),
    results: null,
  };
  const text = JSON.stringify(head, null, 2);
  const body = results.map(pyJson).join(',\n    ');
  return text.replace('"results": null', results.length ? '"results": [\n    ' + body + '\n  ]' : '"results": []') + '\n';
}

/** Writes the results file atomically (a reader never sees half of it). */
function writeResults(file, vectorsDir, implementation, results, unsupported) {
  const tmp = file + '.tmp';
  fs.writeFileSync(tmp, resultsText(file, vectorsDir, implementation, results, unsupported));
  fs.renameSync(tmp, file);
}

module.exports = {Implementation, resultsText, writeResults, pyJson};
