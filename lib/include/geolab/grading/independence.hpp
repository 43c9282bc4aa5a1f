#pragma once
//! \file grading/independence.hpp
//! DESIGN.md rule 6, measured: a test of Task k never depends on the student's answer to another task, so a bug
//! costs the points of its own task only. The check grades the course's reference once per task file with that
//! one file replaced by its untouched stub (the course build's own objects, relinked as `geolab mutate` relinks;
//! trusted code, so every test of a variant runs in one process, self-judged) and compares what each stub costs:
//!  - every task file's stub costs points (else its functions are not tested);
//!  - no test loses points to the stub of a file other than its task's owner: the file the lab header's task
//!    table names for the task (else the most specific file whose stub fails all its tests);
//!  - tests declared to build on other tasks (geolab::builds_on, geolab::whole_chain: grading/chain.hpp) may fail
//!    with those tasks' files stubbed; they are listed, and a declaration no stub needs is a problem.
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "geolab/grading/runner.hpp"

namespace geolab::grading {

//! Where and how to check one lab.
struct IndependenceOptions {
    std::filesystem::path course_root;  //!< the course tree (solutions/ and labs/)
    std::filesystem::path build_dir;    //!< its Ninja build (test_NN_solution, judge_NN, the lab objects)
    std::filesystem::path work_dir;     //!< scratch: the relinked programs (e.g. BUILD/independence/NN)
    std::string lab;                    //!< e.g. "08_voxelize"
    int jobs = 2;                       //!< variants linked and run at once
    double timeout_s = 20;              //!< a test's limit when its listing gives none
    std::function<void(const std::string&)> progress;  //!< one line per step (may be empty)
};

//! The reference with one file stubbed.
struct StubbedFile {
    std::string file;                         //!< e.g. "surface.cpp"
    std::map<std::string, std::string> failed;  //!< graded test -> its status and first message (failed tests only)
    std::string error;                        //!< the variant could not be linked or run (then failed is empty)
    double seconds = 0;                       //!< wall time of its link and run
};

//! What the check found.
struct IndependenceReport {
    std::string lab;
    std::vector<TestInfo> tests;        //!< the graded tests (points > 0), declared ones included
    std::vector<StubbedFile> stubbed;   //!< one per task file, in name order
    std::map<std::string, std::string> owner;  //!< task -> the file whose stub costs it the most
    std::vector<std::string> problems;  //!< each a sentence naming the task, the file and the tests; empty: OK
    std::vector<std::string> notes;     //!< the declared tests and the stubs that fail them
    double seconds = 0;
    bool ok() const { return problems.empty(); }
    //! The table a person reads: per file, the points each task loses; then the problems and notes.
    std::string text() const;
};

//! Runs the check. \throw std::runtime_error when the course build lacks what it needs (no solutions, no
//! test_NN_solution, no compile command) or the reference itself fails a test when its tests share one process.
IndependenceReport check_independence(const IndependenceOptions& opt);

}  // namespace geolab::grading
