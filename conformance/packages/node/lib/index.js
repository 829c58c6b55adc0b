'use strict';
/* rotorcert-vectors: certify a rotation library written in JavaScript against rotorcert's JSON test
 * vectors (conformance/VECTORS.md of rotorcert). The same reader, status rule (RESULT-2) and writer
 * as the Python package rotorcert_vectors; README.md documents the API.
 *
 *   new Implementation({name, scalar, ops, version, description, claimedClauses, claimedLevels,
 *                       preconditions, conventions})    what is certified; ops = {ABI op: function}
 *   certify(t, implementation, {vectors, results, rotorcert, report})   node:test subtests
 *   run(implementation, vectors, resultsPath) -> Run     every vector; writes the results file
 *   runAdapter(argv, description, implementation, ops)   an adapter script's command line
 *   check(resultsPath, {rotorcert, out, vectors}) -> Certificate         `rotorcert vectors check`
 *   VectorSet, VectorFile, Vector; call(op, fn, args) -> Outcome; runFile; roundTrip(log, exp)
 *   watch(...objects): library objects built from the inputs, checked for in-place changes (HYG-1)
 *   writeResults, resultsText, hexfloat, parseHexfloat, decodeValue, checkHexfloat
 *   DidNotReturn, AdapterError, VectorsError, CheckError */

const abi = require('./abi');
const hex = require('./hexfloat');
const outcome = require('./outcome');
const results = require('./results');
const runner = require('./runner');
const vectors = require('./vectors');
const checkMod = require('./check');
const {certify} = require('./node_test');

module.exports = {
  ...abi,
  hexfloat: hex.hexfloat, parseHexfloat: hex.parseHexfloat, decodeValue: hex.decodeValue, checkHexfloat: hex.checkHexfloat,
  ...outcome,
  Implementation: results.Implementation, writeResults: results.writeResults, resultsText: results.resultsText,
  runFile: runner.runFile, Run: runner.Run, run: runner.run, runAdapter: runner.runAdapter,
  VectorSet: vectors.VectorSet, VectorFile: vectors.VectorFile, Vector: vectors.Vector, VectorsError: vectors.VectorsError,
  check: checkMod.check, Certificate: checkMod.Certificate, ClauseResult: checkMod.ClauseResult, CheckError: checkMod.CheckError,
  certify,
  version: require('../package.json').version,
};
