#pragma once
// The sub-commands of the geolab program. Each add_* registers its sub-command on the app; the callback runs
// when it is chosen and sets the exit status through `status`.
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace geolab::cli {

//! The labs this build knows, e.g. {"01_halfedge", "09_spherical_dc"}.
std::vector<std::string> known_labs();
//! "1", "01", "01_halfedge" → "01_halfedge". \throw CLI::ValidationError for an unknown lab.
std::string resolve_lab(const std::string& arg);
//! The folder holding the geolab program and every other built program (test_*, demo_*).
std::filesystem::path bin_dir();
//! The course tree this program was built from.
std::filesystem::path source_dir();

void add_grade(CLI::App& app, int& status);
void add_release(CLI::App& app, int& status);
void add_demo(CLI::App& app, int& status);
void add_info(CLI::App& app, int& status);

}  // namespace geolab::cli
