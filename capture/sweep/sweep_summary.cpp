#include "capture/sweep/sweep_summary.h"

#include <cstdio>

namespace ds::capture::sweep {
namespace {

using nlohmann::json;

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", seconds);
    return text;
}

// The failure lines of one job: its own, then the baseline's regressions.
std::vector<std::string> failure_lines(const JobOutcome& o, const BaselineReport* baseline) {
    std::vector<std::string> lines;
    if (o.status() != "passed") lines.push_back(o.message());
    if (baseline && baseline->jobs.count(o.job.id))
        for (const std::string& r : baseline->jobs.at(o.job.id).regressions)
            lines.push_back("baseline: " + r);
    return lines;
}

void add_testcase(std::string& xml, const JobOutcome& o, const BaselineReport* baseline) {
    xml += "    <testcase classname=\"" + xml_escaped(o.job.scene) + "\" name=\"" +
           xml_escaped(o.job.name()) + "\"";
    if (o.result) xml += " time=\"" + seconds_text(o.seconds()) + "\"";
    const std::vector<std::string> failures = failure_lines(o, baseline);
    if (failures.empty()) {
        xml += "/>\n";
        return;
    }
    const std::string type = o.status() == "passed" ? "regression" : o.status();
    std::string body = "job " + o.job.id;
    for (const std::string& line : failures) body += "\n" + line;
    xml += ">\n      <failure type=\"" + xml_escaped(type) + "\" message=\"" +
           xml_escaped(failures.front()) + "\">" + xml_escaped(body) + "</failure>\n";
    xml += "    </testcase>\n";
}

}  // namespace

std::string JobOutcome::status() const {
    if (!result) return "no result";
    return result->value("status", "failed");
}

std::string JobOutcome::message() const {
    if (!result)
        return "no result: the job's folder jobs/" + job.id +
               "/ is missing (never run, or killed before it finished)";
    return result->value("message", "");
}

double JobOutcome::seconds() const {
    return result ? result->value("seconds", 0.0) : 0.0;
}

int BaselineReport::regression_count() const {
    size_t n = regressions.size();
    for (const auto& [id, c] : jobs) n += c.regressions.size();
    return int(n);
}

json sweep_json(const std::vector<JobOutcome>& outcomes) {
    json results = json::array(), devices = json::array();
    int passed = 0, failed = 0, missing = 0;
    for (const JobOutcome& o : outcomes) {
        const std::string status = o.status();
        (status == "passed" ? passed : status == "failed" ? failed : missing) += 1;
        json r = {{"id", o.job.id},
                  {"scene", o.job.scene},
                  {"name", o.job.name()},
                  {"action", action_name(o.job.action.kind)},
                  {"status", status}};
        if (status != "passed") r["message"] = o.message();
        for (const char* key : {"device", "counts", "lint"})
            if (o.result && o.result->contains(key)) r[key] = o.result->at(key);
        if (r.contains("device") &&
            std::find(devices.begin(), devices.end(), r["device"]) == devices.end())
            devices.push_back(r["device"]);
        results.push_back(r);
    }
    return {{"tool", "depthscope"}, {"jobs", outcomes.size()}, {"passed", passed},
            {"failed", failed},     {"no_result", missing},    {"devices", devices},
            {"results", results}};
}

std::string junit_xml(const std::vector<JobOutcome>& outcomes, const BaselineReport* baseline) {
    int failures = 0;
    double seconds = 0;
    for (const JobOutcome& o : outcomes) {
        failures += failure_lines(o, baseline).empty() ? 0 : 1;
        seconds += o.seconds();
    }
    const std::string counts = " tests=\"" + std::to_string(outcomes.size()) + "\" failures=\"" +
                               std::to_string(failures) + "\" errors=\"0\" skipped=\"0\"";
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += "<testsuites name=\"depthscope sweep\"" + counts + ">\n";
    xml += "  <testsuite name=\"depthscope sweep\"" + counts + " time=\"" + seconds_text(seconds) +
           "\">\n";
    for (const JobOutcome& o : outcomes) add_testcase(xml, o, baseline);
    xml += "  </testsuite>\n</testsuites>\n";
    return xml;
}

std::string xml_escaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
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
                out += byte < 0x20 && c != '\t' && c != '\n' && c != '\r' ? '?' : c;
        }
    }
    return out;
}

}  // namespace ds::capture::sweep
