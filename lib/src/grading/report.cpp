#include "geolab/grading/report.hpp"

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

namespace geolab::grading {
namespace {

std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\t') c = ' ';
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

std::string fmt_points(double p) {
    std::ostringstream os;
    os << std::setprecision(4) << p;
    return os.str();
}

std::string number_of(std::size_t lab, std::size_t test) { return std::to_string(lab + 1) + "." + std::to_string(test + 1); }

// The text a student reads for one test: status, messages, hint, and (capped) what it printed.
std::string test_output(const TestResult& r, bool with_output) {
    std::ostringstream os;
    os << to_string(r.status) << " (" << std::fixed << std::setprecision(2) << r.seconds << " s)\n";
    for (const auto& m : r.messages) os << m << "\n";
    if (r.status != Status::passed && !r.info.hint.empty()) os << "Hint: " << r.info.hint << "\n";
    for (const auto& f : r.figures) os << "Figure: " << f << "\n";
    if (with_output && r.status != Status::passed && !r.output.empty()) {
        std::string out = r.output.size() > 4000 ? r.output.substr(0, 4000) + "\n...(cut)" : r.output;
        os << "--- output ---\n" << out << "\n";
    }
    return os.str();
}

std::string xml_escape(const std::string& text) {
    const std::string s = valid_utf8(text);
    std::string o;
    for (unsigned char c : s) {
        switch (c) {
            case '&': o += "&amp;"; break;
            case '<': o += "&lt;"; break;
            case '>': o += "&gt;"; break;
            case '"': o += "&quot;"; break;
            default:
                if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) o += ' ';
                else o += static_cast<char>(c);
        }
    }
    return o;
}

}  // namespace

std::string valid_utf8(const std::string& s) {
    std::string o;
    o.reserve(s.size());
    const auto* p = reinterpret_cast<const unsigned char*>(s.data());
    const std::size_t n = s.size();
    for (std::size_t i = 0; i < n;) {
        const unsigned char c = p[i];
        std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
        bool ok = len > 0 && i + len <= n;
        for (std::size_t k = 1; ok && k < len; ++k) ok = (p[i + k] & 0xc0) == 0x80;
        if (ok && len > 1) {
            // No overlong forms, no surrogates, nothing above U+10FFFF.
            unsigned cp = c & (0x7f >> len);
            for (std::size_t k = 1; k < len; ++k) cp = (cp << 6) | (p[i + k] & 0x3f);
            ok = (len == 2 && cp >= 0x80) || (len == 3 && cp >= 0x800 && (cp < 0xd800 || cp > 0xdfff)) ||
                 (len == 4 && cp >= 0x10000 && cp <= 0x10ffff);
        }
        if (ok) {
            o.append(s, i, len);
            i += len;
        } else {
            o += "\xef\xbf\xbd";
            ++i;
        }
    }
    return o;
}

std::string first_message(const TestResult& r, std::size_t max_chars) {
    if (r.messages.empty()) return "";
    std::string m = one_line(r.messages.front());
    if (m.size() > max_chars) m = m.substr(0, max_chars - 3) + "...";
    return m;
}

void print_console(std::ostream& os, const std::vector<LabReport>& labs, HiddenPolicy hidden, bool color,
                   bool verbose) {
    auto paint = [&](Status s, const std::string& text) {
        if (!color) return text;
        const char* c = s == Status::passed ? "\033[32m" : s == Status::not_implemented ? "\033[33m" : "\033[31m";
        return std::string(c) + text + "\033[0m";
    };
    const std::string indent = "        ";
    // A whole message, every line indented; without --verbose at most 40 lines.
    auto print_message = [&](const std::string& m, const std::string& first_prefix) {
        std::istringstream lines(m);
        std::string line;
        std::size_t n = 0;
        bool first = true;
        while (std::getline(lines, line)) {
            if (line.empty()) continue;
            if (!verbose && ++n > 40) {
                os << indent << "... (--verbose shows the whole message)\n";
                break;
            }
            os << indent << (first ? first_prefix : "") << line << "\n";
            first = false;
        }
    };
    for (const auto& lab : labs) {
        os << "\n== lab " << lab.lab << " (" << lab.variant << ") ==\n";
        if (!lab.error.empty()) {
            os << "could not run the tests: " << lab.error << "\nno score: the tests did not run\n";
            continue;
        }
        std::string suite;
        for (const auto& r : lab.results) {
            if (r.info.suite != suite) {
                suite = r.info.suite;
                os << "\n  " << (suite.empty() ? "(no task)" : suite) << "\n";
            }
            const bool withhold = r.info.hidden && hidden == HiddenPolicy::name_points;
            const std::string status = to_string(r.status);
            os << "  " << paint(r.status, (r.status == Status::passed ? "PASS " : "FAIL ")) << std::setw(5)
               << (fmt_points(r.score) + "/" + fmt_points(r.info.points)) << "  " << r.info.name
               << (r.info.hidden ? "  [hidden]" : "") << "\n";
            if (r.status != Status::passed && !withhold) {
                // The status word once: a message that starts with it ("not implemented: f", "crashed with")
                // is not prefixed again.
                const std::string m = r.messages.empty() ? std::string() : r.messages.front();
                const bool says_status = m.rfind(status, 0) == 0;
                if (m.empty()) os << indent << status << "\n";
                else print_message(m, says_status ? "" : status + ": ");
                const std::size_t shown = verbose ? r.messages.size() : 1;
                for (std::size_t k = 1; k < shown; ++k) print_message(r.messages[k], "");
                if (!verbose && r.messages.size() > 1)
                    os << indent << "(" << r.messages.size() - 1 << " more message" << (r.messages.size() > 2 ? "s" : "")
                       << ": --verbose)\n";
                if (!r.info.hint.empty()) os << indent << "hint: " << r.info.hint << "\n";
                for (const auto& f : r.figures) os << indent << "figure: " << f << "\n";
                if (verbose && !r.output.empty()) {
                    os << indent << "--- what the test printed ---\n";
                    print_message(r.output.size() > 20000 ? r.output.substr(0, 20000) + "\n...(cut)" : r.output, "");
                }
            }
        }
        // Totals per task: partial credit is visible at a glance.
        std::map<std::string, std::pair<double, double>> per_task;
        std::vector<std::string> order;
        std::map<Status, int> counts;
        for (const auto& r : lab.results) {
            if (!per_task.count(r.info.suite)) order.push_back(r.info.suite);
            per_task[r.info.suite].first += r.score;
            per_task[r.info.suite].second += r.info.points;
            ++counts[r.status];
        }
        os << "\n  per task:\n";
        for (const auto& s : order)
            os << "    " << std::setw(7) << (fmt_points(per_task[s].first) + "/" + fmt_points(per_task[s].second))
               << "  " << (s.empty() ? "(no task)" : s) << "\n";
        os << "  tests: " << lab.results.size();
        for (auto [s, n] : counts) os << ", " << n << " " << to_string(s);
        os << "\n  score: " << fmt_points(lab.score()) << " / " << fmt_points(lab.max_score()) << "  ("
           << std::fixed << std::setprecision(1) << lab.seconds << " s)\n";
        os.unsetf(std::ios::fixed);
    }
}

void write_gradescope_json(const std::filesystem::path& file, const std::vector<LabReport>& labs,
                           const std::string& preamble) {
    nlohmann::json tests = nlohmann::json::array();
    double score = 0, max_score = 0, seconds = 0;
    std::ostringstream summary;
    summary << preamble;
    for (std::size_t l = 0; l < labs.size(); ++l) {
        const auto& lab = labs[l];
        seconds += lab.seconds;
        if (!lab.error.empty()) summary << "lab " << lab.lab << ": could not run the tests: " << lab.error << "\n";
        for (std::size_t t = 0; t < lab.results.size(); ++t) {
            const auto& r = lab.results[t];
            score += r.score;
            max_score += r.info.points;
            nlohmann::json tags = {lab.lab, to_string(r.status)};
            if (!r.info.suite.empty()) tags.push_back(r.info.suite);
            tests.push_back({{"name", valid_utf8(r.info.name)},
                             {"number", number_of(l, t)},
                             {"score", r.score},
                             {"max_score", r.info.points},
                             {"status", r.status == Status::passed ? "passed" : "failed"},
                             {"output", valid_utf8(test_output(r, true))},
                             {"tags", tags},
                             {"visibility", r.info.hidden ? "after_published" : "visible"}});
        }
        summary << "lab " << lab.lab << ": " << fmt_points(lab.score()) << " / " << fmt_points(lab.max_score()) << "\n";
    }
    nlohmann::json j = {{"score", score},
                        {"max_score", max_score},
                        {"execution_time", seconds},
                        {"output", valid_utf8(summary.str())},
                        {"visibility", "visible"},
                        {"stdout_visibility", "hidden"},
                        {"tests", tests}};
    std::ofstream f(file);
    // Every string is valid UTF-8 already; `replace` is the last guard (a tag, a suite name).
    f << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    if (!f) throw std::runtime_error(file.string() + ": cannot write the results file");
}

void write_junit(const std::filesystem::path& file, const std::vector<LabReport>& labs) {
    std::ofstream f(file);
    f << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n";
    for (const auto& lab : labs) {
        int failures = 0, errors = 0;
        for (const auto& r : lab.results) {
            if (r.status == Status::failed || r.status == Status::not_implemented) ++failures;
            if (r.status == Status::crashed || r.status == Status::timeout || r.status == Status::error) ++errors;
        }
        if (!lab.error.empty()) ++errors;
        f << "  <testsuite name=\"" << xml_escape(lab.lab + " (" + lab.variant + ")") << "\" tests=\""
          << lab.results.size() << "\" failures=\"" << failures << "\" errors=\"" << errors << "\" time=\""
          << lab.seconds << "\">\n";
        if (!lab.error.empty())
            f << "    <testcase name=\"(listing)\" classname=\"" << xml_escape(lab.lab) << "\"><error message=\""
              << xml_escape(lab.error) << "\"/></testcase>\n";
        for (const auto& r : lab.results) {
            f << "    <testcase name=\"" << xml_escape(r.info.name) << "\" classname=\""
              << xml_escape(lab.lab + "." + r.info.suite) << "\" time=\"" << r.seconds << "\">";
            if (r.status != Status::passed) {
                const char* tag = (r.status == Status::failed || r.status == Status::not_implemented) ? "failure" : "error";
                f << "\n      <" << tag << " type=\"" << to_string(r.status) << "\" message=\""
                  << xml_escape(first_message(r)) << "\">" << xml_escape(test_output(r, false)) << "</" << tag
                  << ">\n    ";
            }
            f << "</testcase>\n";
        }
        f << "  </testsuite>\n";
    }
    f << "</testsuites>\n";
    if (!f) throw std::runtime_error(file.string() + ": cannot write the JUnit file");
}

}  // namespace geolab::grading
