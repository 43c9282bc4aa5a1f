#pragma once
//! \file grading/report.hpp
//! The grader's reports: a console table a student understands, Gradescope's results.json, and JUnit XML.
#include <filesystem>
#include <ostream>
#include <vector>

#include "geolab/grading/runner.hpp"

namespace geolab::grading {

//! What a report shows of hidden tests.
enum class HiddenPolicy {
    show,         //!< instructor's view: everything
    name_points,  //!< student's view before release: name, points and pass/fail only
};

//! The console table: test, points, status, the whole first failure message (the status word once), the hint;
//! then totals per task. `verbose`: every message, uncut, and what the test printed.
void print_console(std::ostream& os, const std::vector<LabReport>& labs, HiddenPolicy hidden, bool color,
                   bool verbose = false);

//! Gradescope's results.json (score, max_score, execution_time, output, tests[] with name, number, score,
//! max_score, status, output, visibility, tags). Hidden tests get visibility "after_published".
//! `preamble` goes first in the top-level output (e.g. the compiler's messages of a submission).
void write_gradescope_json(const std::filesystem::path& file, const std::vector<LabReport>& labs,
                           const std::string& preamble = "");

//! JUnit XML: one <testsuite> per lab and variant, one <testcase> per test (failure / error / skipped).
void write_junit(const std::filesystem::path& file, const std::vector<LabReport>& labs);

//! `s` with every byte that is not part of valid UTF-8 (a stray \xff, a cut sequence, an overlong form, a
//! surrogate) replaced by U+FFFD: a test may print anything, and JSON and XML readers accept only valid text.
std::string valid_utf8(const std::string& s);

//! The message of a result as shown to a student: the first message, shortened.
std::string first_message(const TestResult& r, std::size_t max_chars = 300);

}  // namespace geolab::grading
