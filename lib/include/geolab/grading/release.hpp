#pragma once
//! \file grading/release.hpp
//! The single-source rule: answers live only in solutions/. labs/NN/src is generated from solutions/NN/src by
//! replacing every block
//!     // BEGIN SOLUTION
//!     ...
//!     // END SOLUTION
//! with `throw geolab::NotImplemented(__func__);` at the block's indentation, or with the block's
//! `// STUB: <code>` lines (uncommented) when it has any. Unterminated, nested or stray markers are errors.
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace geolab::grading {

//! The student version of one solution file. \throw std::runtime_error "NAME:LINE: reason" on a bad marker.
std::string strip_solutions(const std::string& text, const std::string& name);

//! The given files of a lab (code students read but do not write): the basenames listed in
//! `lab_dir/given.txt`, one per line, '#' comments. The grader always takes them from the course tree, whatever a
//! submission holds; the generator checks that each has no solution block and that every solutions/ file without
//! one is listed. Empty when the file does not exist. \throw std::runtime_error "FILE:LINE: reason" on a bad entry.
std::set<std::string> given_files(const std::filesystem::path& lab_dir);

//! One difference between labs/ and what the generator makes from solutions/.
struct LabDiff {
    std::filesystem::path file;  //!< relative to the course tree
    std::string reason;          //!< "differs", "missing", "not generated from solutions/"
};

//! Regenerate every labs/NN/src/*.cpp from solutions/NN/src/*.cpp under `root`. With write = false only
//! compares; returns the differences (empty: labs/ is exactly what the generator makes).
std::vector<LabDiff> generate_labs(const std::filesystem::path& root, bool write);

//! The student release's README.md, relative to the course tree: it replaces the instructor's README.md.
inline constexpr const char* release_readme_template = "tools/release/README.md";

//! The files git tracks in the work tree `root` (`git ls-files`), relative to it, sorted.
//! \throw std::runtime_error when git is missing or `root` is not a git work tree.
std::vector<std::filesystem::path> tracked_files(const std::filesystem::path& root);

//! Write the student release of the course tree `root` into `out` (which must not exist or be empty). It copies
//! only the files git tracks (an untracked screenshot or notes file never ships), minus solutions/, hidden tests,
//! the adversarial grader cases, build and model folders; README.md comes from release_readme_template; labs/ is
//! regenerated. Then every file is scanned for leaks (a marker, or any line that exists only inside a solution
//! block). With `git_init`, `out` becomes a fresh repository with one commit (no history to leak answers from).
//! \return the files written. \throw std::runtime_error on a leak (file:line named), when `root` is not a git
//! work tree, or on an I/O error.
std::vector<std::filesystem::path> make_release(const std::filesystem::path& root, const std::filesystem::path& out,
                                                bool git_init = true);

}  // namespace geolab::grading
