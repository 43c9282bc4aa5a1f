#pragma once
// The sub-commands of the geolab program. Each add_* registers its sub-command on the app; the callback runs
// when it is chosen and sets the exit status through `status`.
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "geolab/grading/submission.hpp"

namespace geolab::cli {

//! The labs this build knows, e.g. {"01_halfedge", "09_spherical_dc"}.
std::vector<std::string> known_labs();
//! "1", "01", "01_halfedge" → "01_halfedge". \throw CLI::ValidationError for an unknown lab.
std::string resolve_lab(const std::string& arg);
//! The folder holding the geolab program and every other built program (test_*, demo_*).
std::filesystem::path bin_dir();
//! The course tree this program was built from.
std::filesystem::path source_dir();

//! The options to grade a submission of `lab` in work folder number `job` under `work_dir` (default
//! BUILD/grading): the course tree and build this program belongs to.
grading::SubmissionOptions submission_options(const std::string& lab, const std::string& work_dir, int job);
//! Write results.json (the submission's summary first in its output) and JUnit XML, where asked (non-empty).
void write_submission_reports(const grading::SubmissionReport& rep, const std::string& json, const std::string& junit);

void add_grade(CLI::App& app, int& status);
void add_grade_all(CLI::App& app, int& status);
void add_gradescope(CLI::App& app, int& status);
void add_release(CLI::App& app, int& status);
void add_demo(CLI::App& app, int& status);
void add_info(CLI::App& app, int& status);
void add_contour(CLI::App& app, int& status);
void add_table1(CLI::App& app, int& status);
void add_mutate(CLI::App& app, int& status);
void add_quadric(CLI::App& app, int& status);
void add_blobby(CLI::App& app, int& status);
void add_sweep(CLI::App& app, int& status);
void add_csg(CLI::App& app, int& status);
void add_voxelize(CLI::App& app, int& status);

}  // namespace geolab::cli
