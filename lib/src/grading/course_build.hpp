#pragma once
// What the grader reads from the course's Ninja build, and how it runs trusted tools (internal to
// lib/src/grading; defined in submission.cpp).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "geolab/grading/runner.hpp"

namespace geolab::grading::detail {

//! Run a trusted command (unzip, nm, ninja, the linker) with plain limits, no sandbox.
CommandResult run_plain(const std::vector<std::string>& argv, double timeout_s, std::size_t memory_mb = 0,
                        std::size_t output_cap = 4 << 20);

//! The course's compile command of one source file (the first entry of compile_commands.json for it), split
//! into arguments. \throw std::runtime_error naming the file when the build has none.
std::vector<std::string> compile_command(const std::filesystem::path& build, const std::filesystem::path& source);

//! The course's link command of `target` (e.g. "test_01_halfedge": the last command ninja would run for it),
//! split into arguments. \throw std::runtime_error when ninja cannot say.
std::vector<std::string> link_command(const std::filesystem::path& build, const std::string& target);

}  // namespace geolab::grading::detail
