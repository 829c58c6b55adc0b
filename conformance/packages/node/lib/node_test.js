'use strict';
/* Certifying a library from node's built-in test runner (node:test):
 *
 *   const {test} = require('node:test');
 *   const {certify, Implementation} = require('rotorcert-vectors');
 *   test('rotorcert', (t) => certify(t, impl, {vectors: 'vectors', results: 'results.json', rotorcert: 'rotorcert'}));
 *
 * certify() makes one subtest per vector file the implementation answers, named `CLAUSE[op]`, which
 * calls the op's function on every vector of the file under the one status rule (RESULT-2,
 * ./outcome.js). A subtest fails, naming the vector id and its input in hexfloat, when the function
 * has a defect rather than an answer (a ReferenceError, TypeError, a wrong number of outputs); a
 * refusal of the library is its answer and is graded, not failed here. A last subtest writes the
 * results file: `certificate` when options.rotorcert names the rotorcert executable (it then runs
 * `rotorcert vectors check` and fails when a claimed clause does not pass, listing those clauses),
 * else `results`. */

const path = require('path');
const {AdapterError} = require('./outcome');
const {writeResults} = require('./results');
const {runFile, refusalKey} = require('./runner');
const {VectorSet} = require('./vectors');
const {check} = require('./check');

/** An Error whose printed stack is its message and the cause's frames (not this package's). */
function reportable(message, cause) {
  const err = new Error(message);
  const frames = cause && typeof cause.stack === 'string'
    ? cause.stack.split('\n').filter((l) => /^\s+at /.test(l) && !l.includes(__dirname + path.sep)) : [];
  err.stack = [message, ...(cause ? [`${cause.name}: ${cause.message}`] : []), ...frames].join('\n');
  return err;
}

/** The options the environment gives: ROTORCERT_VECTORS, ROTORCERT_RESULTS, ROTORCERT_CHECK,
 *  ROTORCERT_REPORT (so that `node --test` takes them without a command line of its own). */
function fromEnvironment() {
  const env = process.env, options = {};
  if (env.ROTORCERT_VECTORS) options.vectors = env.ROTORCERT_VECTORS;
  if (env.ROTORCERT_RESULTS) options.results = env.ROTORCERT_RESULTS;
  if (env.ROTORCERT_CHECK) options.rotorcert = env.ROTORCERT_CHECK;
  if (env.ROTORCERT_REPORT) options.report = env.ROTORCERT_REPORT;
  return options;
}

/** Certifies `implementation` (an Implementation) in the test context t (or node:test's `test`
 *  function, for top-level tests). options, each defaulting to its environment variable:
 *  vectors (ROTORCERT_VECTORS: the export's directory or index.json; without it the test is
 *  skipped), results (ROTORCERT_RESULTS: the results file, default 'rotorcert-results.json'),
 *  rotorcert (ROTORCERT_CHECK: the rotorcert executable; adds the `certificate` subtest), report
 *  (ROTORCERT_REPORT: where `vectors check` writes report.json/.md/.html, default
 *  rotorcert-report beside the results file). Resolves, once every subtest has finished, to
 *  {resultsPath, results, refused, certificate}, or null when skipped. */
async function certify(t, implementation, options = {}) {
  options = Object.assign(fromEnvironment(), options);
  const subtest = typeof t === 'function' ? t : t.test.bind(t);
  if (!options.vectors) {
    const why = 'no vectors to certify against: set ROTORCERT_VECTORS (or options.vectors) to an export of ' +
                '`rotorcert vectors export`';
    if (typeof t === 'function') await subtest('rotorcert', {skip: why}, () => {});
    else t.skip(why);
    return null;
  }
  const vectorSet = new VectorSet(options.vectors);
  const resultsPath = path.resolve(options.results || 'rotorcert-results.json');
  const reportDir = path.resolve(options.report || path.join(path.dirname(resultsPath), 'rotorcert-report'));
  const files = vectorSet.files(implementation.numberFormat, implementation.ops);
  const outcomes = new Map();   // VectorFile.file -> [[vector, Outcome]]
  const started = new Set();    // subtests that ran (--test-name-pattern may leave some out)
  const state = {resultsPath, results: null, refused: null, certificate: null};

  const write = () => {
    const results = [], refused = {};
    for (const vf of files) {
      for (const [vector, outcome] of outcomes.get(vf.file) || []) {
        results.push(outcome.result(vector.id));
        if (outcome.refusal) { const k = refusalKey(vf.op, outcome); refused[k] = (refused[k] || 0) + 1; }
      }
    }
    writeResults(resultsPath, vectorSet.directory, implementation, results, implementation.unsupportedOps);
    state.results = results;
    state.refused = refused;
  };

  const pending = files.map((vf) => subtest(`${vf.clause}[${vf.op}]`, () => {
    started.add(vf.file);
    try {
      outcomes.set(vf.file, runFile(vf, implementation.ops[vf.op]));
    } catch (e) {
      if (e instanceof AdapterError) throw reportable(e.message, e.cause);
      throw e;
    }
  }));
  if (!files.length) {
    pending.push(subtest('vectors', () => {
      throw new Error(`${vectorSet.indexPath} has no vectors of ${implementation.numberFormat} for the ops of ` +
                      `${implementation.name} (${Object.keys(implementation.ops).sort().join(', ')}): export them ` +
                      `with \`rotorcert vectors export --scalar ${implementation.scalar}\``);
    }));
  }
  pending.push(subtest(options.rotorcert ? 'certificate' : 'results', (tc) => {
    write();
    if (!options.rotorcert) return;
    if (started.size < files.length) {
      tc.skip(`${files.length - started.size} of ${files.length} vector subtests did not run: a certificate needs all of them`);
      return;
    }
    const cert = check(resultsPath, {rotorcert: options.rotorcert, out: reportDir, vectors: vectorSet.indexPath});
    state.certificate = cert;
    if (!cert.passed) {
      const failed = cert.failedClauses().map((c) => c.id);
      throw reportable([`rotorcert vectors check ${resultsPath}: exit ${cert.exitCode}, ${cert.claim()}`,
                        `claimed clauses that do not pass: ${failed.join(', ') || '(see the certificate)'}`,
                        '', cert.output.trimEnd()].join('\n'));
    }
  }));
  await Promise.all(pending);
  if (state.results === null) write();  // the last subtest was filtered out: write what ran
  return state;
}

module.exports = {certify, fromEnvironment};
