// report.json, format "rotorcert-report" version 1 (schema spec/report.schema.json): where typed
// certificates leave the tool. Everything the document says about a certificate (levels, claim,
// accuracy, conventions, as expected) comes from verdict.hpp; nothing here judges.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/certify/certificate.hpp>
#include <rotorcert/spec/spec.hpp>

namespace rotorcert::certify {

/// One certificate in the report.json format.
json certificate_json(const Certificate& c);

/// A certificate read back from report.json (where data enters: `rotorcert diff`): the table, the
/// levels certified, the clause results (their summaries: report.json keeps no error lists), the
/// known defects and the reproduce commands. Throws std::runtime_error naming the field that is
/// missing or malformed.
Certificate certificate_from_json(const json& j);

/// Every certificate of a report.json document: its implementations, then those of its
/// third-party section.
std::vector<Certificate> certificates_of_report(const json& report);

/// What a report's exit code asks of its certificates: `report` and `third-party` runs ask that
/// every table is as expected (known defects FAIL, the rest passes), `certify`, `vectors-check`
/// and `bench` that every claimed clause passes.
bool report_ok(const std::string& kind, const std::vector<Certificate>& certificates);

/// The whole report.json object. `run` is the only part allowed to differ between runs with the
/// same options (timings, date, host).
json report_json(const spec::Spec& spec, const std::string& kind, const json& options, const json& run,
                 const std::vector<Certificate>& certificates);

// Writing it (JSON, Markdown, HTML) is the report layer's: rotorcert/report/write.hpp.

}  // namespace rotorcert::certify
