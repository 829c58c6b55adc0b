'use strict';
/* Reading an export of `rotorcert vectors export`: index.json and the vector files it lists
 * (formats rotorcert-vectors-index and rotorcert-vectors, version 1, conformance/VECTORS.md). */

const fs = require('fs');
const path = require('path');
const {decodeValue} = require('./hexfloat');

/** An export that cannot be read: missing, of another format, or malformed. */
class VectorsError extends Error {
  constructor(message) { super(message); this.name = 'VectorsError'; }
}

function loadJson(file, what) {
  let text;
  try {
    text = fs.readFileSync(file, 'utf8');
  } catch (e) {
    throw new VectorsError(`cannot read ${what} ${file}: ${e.message}`);
  }
  try {
    return JSON.parse(text);
  } catch (e) {
    throw new VectorsError(`${file} is not JSON: ${e.message}`);
  }
}

function checkFormat(doc, file, format) {
  if (doc === null || typeof doc !== 'object' || doc.format !== format || doc.format_version !== 1)
    throw new VectorsError(`${file}: not a ${format} file of format_version 1`);
}

/** One test of a vector file: its id (CLAUSE/op/format/tcId), what it probes, its inputs. */
class Vector {
  constructor(file, test) {
    this.file = file;
    this.id = test.id;
    this.tcId = test.tcId;
    this.comment = test.comment || '';
    this.flags = test.flags || [];
    this.k = test.k || 0;
    this.result = test.result;                      // valid | invalid | acceptable
    this.expectedStatus = test.expected ? test.expected.status : undefined;
    this.hexInputs = {};
    for (const [name, arr] of Object.entries(test.in)) this.hexInputs[name] = arr.hex;
  }

  /** The inputs as the op's function takes them, in the file's input order: one element per input
   *  (an array of `stride` numbers, or a number when the stride is 1); an input given per influence
   *  (n-way ops) is an array of k such elements. Values are exact (decodeValue). */
  arguments() {
    return this.file.layout.map(([name, stride, perInfluence]) => {
      const values = this.hexInputs[name].map(decodeValue);
      if (perInfluence) {
        const out = [];
        for (let i = 0; i < this.k; i++) out.push(stride > 1 ? values.slice(i * stride, (i + 1) * stride) : values[i]);
        return out;
      }
      return stride > 1 ? values : values[0];
    });
  }

  /** The inputs in hexfloat as certificates print them: `a=[0x1p+0, ...] t=[0x1p-1]`. */
  describeInputs() {
    return this.file.layout.map(([name]) => `${name}=[${this.hexInputs[name].join(', ')}]`).join(' ');
  }
}

/** One file of an export: the vectors of one (clause, op, number format). The header comes from
 *  index.json; the tests are read on first use. */
class VectorFile {
  constructor(vectorSet, entry) {
    this.vectorSet = vectorSet;
    this.file = entry.file;
    this.path = path.join(vectorSet.directory, entry.file);
    this.clause = entry.clause;
    this.level = entry.level;
    this.op = entry.op;
    this.numberFormat = entry.number_format;
    this.tolerance = entry.tolerance;
    this.numberOfTests = entry.numberOfTests;
    this._doc = null;
    this._vectors = null;
  }

  _load() {
    if (this._doc === null) {
      const doc = loadJson(this.path, 'vector file');
      checkFormat(doc, this.path, 'rotorcert-vectors');
      if (doc.op !== this.op || doc.clause !== this.clause)
        throw new VectorsError(`${this.path}: clause/op ${doc.clause}/${doc.op}, index.json says ${this.clause}/${this.op}`);
      this._doc = doc;
    }
    return this._doc;
  }

  get title() { return this._load().clause_title || ''; }

  /** [name, stride, perInfluence] of each input array, in the op's argument order. */
  get layout() { return this._load().inputs.map((a) => [a.name, a.stride, Boolean(a.per_influence)]); }

  get vectors() {
    if (this._vectors === null) this._vectors = this._load().tests.map((t) => new Vector(this, t));
    return this._vectors;
  }
}

/** An export: `new VectorSet(p)` with the export's directory or its index.json. */
class VectorSet {
  constructor(p) {
    let isDir = false;
    try { isDir = fs.statSync(p).isDirectory(); } catch (e) { /* reported by loadJson */ }
    this.directory = isDir ? p : path.dirname(p);
    this.indexPath = isDir ? path.join(p, 'index.json') : p;
    this.index = loadJson(this.indexPath, 'vectors index');
    checkFormat(this.index, this.indexPath, 'rotorcert-vectors-index');
    if (!Array.isArray(this.index.files)) throw new VectorsError(`${this.indexPath}: malformed files list`);
    this._files = this.index.files.map((e) => new VectorFile(this, e));
  }

  get specVersion() { return this.index.spec_version; }
  get rotorcertVersion() { return this.index.rotorcert_version; }
  get seed() { return this.index.seed; }
  get casesPerFamily() { return this.index.cases_per_family; }

  /** The vector files in index order, of one number format ('binary64') and of the ops of `ops`
   *  (an object keyed by op name, or an array of names) when given. */
  files(numberFormat, ops) {
    const has = ops === undefined ? () => true
      : Array.isArray(ops) ? (op) => ops.includes(op) : (op) => Object.prototype.hasOwnProperty.call(ops, op);
    return this._files.filter((f) => (numberFormat === undefined || f.numberFormat === numberFormat) && has(f.op));
  }
}

module.exports = {Vector, VectorFile, VectorSet, VectorsError};
