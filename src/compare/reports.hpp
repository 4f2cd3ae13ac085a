#pragma once
// The written forms of a comparison (docs/regression.md, "Reports"); each
// returns the whole file's text, for the caller to write atomically.
#include <string>

#include "compare/compare_run.hpp"

namespace facet {

// report.json, schema "facet-compare" version CompareReport::kSchemaVersion.
std::string report_json(const CompareReport& report);

// JUnit XML: one test case per file, failures and errors as CI systems read them.
std::string report_junit(const CompareReport& report);

// One self-contained HTML page (images inlined, no network), failures
// first. Reads the images it shows from disk (the report folder and the
// two runs' files).
std::string report_html(const CompareReport& report);

// Text for XML and HTML: & < > " ' as entities, control characters
// (which XML 1.0 forbids) but tab and newlines as '?'.
std::string escape_markup(const std::string& text);

// Writes report.json, junit.xml and index.html into report.report_dir.
void write_reports(const CompareReport& report);

}  // namespace facet
