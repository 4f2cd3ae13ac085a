// JUnit XML as Jenkins, GitLab and GitHub's test reporters read it: a
// <testsuite> of <testcase>s, a <failure> for a judged difference, an
// <error> for a file that is missing, extra, mismatched or unreadable.
#include "compare/reports.hpp"

namespace facet {

std::string escape_markup(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                // XML 1.0 allows no control characters but tab and newlines.
                if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r')
                    out += '?';
                else
                    out += c;
        }
    }
    return out;
}

std::string report_junit(const CompareReport& report) {
    int failures = 0, errors = 0;
    for (const FileResult& r : report.files) {
        if (r.status == FileStatus::compared && r.outcome == Outcome::fail) ++failures;
        if (r.status != FileStatus::compared && r.status != FileStatus::identical) ++errors;
    }
    const std::string counts = " tests=\"" + std::to_string(report.files.size()) +
                               "\" failures=\"" + std::to_string(failures) + "\" errors=\"" +
                               std::to_string(errors) + "\"";
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += "<testsuites name=\"facet compare\"" + counts + ">\n";
    xml += "  <testsuite name=\"" + escape_markup(report.ref + " vs " + report.candidate) + "\"" +
           counts + " skipped=\"0\">\n";
    for (const FileResult& r : report.files) {
        const std::string classname =
            "facet.compare." + (r.key.camera.empty() ? "" : r.key.camera + ".") + r.key.pass;
        xml += "    <testcase classname=\"" + escape_markup(classname) + "\" name=\"" +
               escape_markup(r.key.label()) + "\"";
        const bool error = r.status != FileStatus::compared && r.status != FileStatus::identical;
        if (!error && r.outcome == Outcome::pass) {
            xml += "/>\n";
            continue;
        }
        xml += ">\n";
        if (error)
            xml += "      <error type=\"" + std::string(file_status_name(r.status)) +
                   "\" message=\"" + escape_markup(r.reason) + "\"/>\n";
        else if (r.outcome == Outcome::fail)
            xml += "      <failure type=\"difference\" message=\"" + escape_markup(r.reason) +
                   "\"/>\n";
        else
            xml += "      <system-out>warning: " + escape_markup(r.reason) + "</system-out>\n";
        xml += "    </testcase>\n";
    }
    xml += "  </testsuite>\n</testsuites>\n";
    return xml;
}

}  // namespace facet
