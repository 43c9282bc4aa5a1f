#pragma once
//! \file grading/submission.hpp
//! Grading one student's submission of one lab against the course tree and its build (hidden tests included).
//!
//! Only the files students may change are taken from the submission: the lab's `labs/NN_x/src/*.cpp`, matched
//! by basename wherever they sit in the submission (folder or zip); every other file is ignored and listed.
//! Lab files the submission lacks get the generated stub. The course build (Ninja, with
//! compile_commands.json) already holds every test object and library: the grader compiles only the student's
//! files with the course's own compile command, in a sandbox, and relinks the lab's test program with the
//! course's own link command. A compile error is a graded result (score 0, the compiler's messages kept).
#include <filesystem>
#include <string>
#include <vector>

#include "geolab/grading/runner.hpp"

namespace geolab::grading {

//! Where to grade and how.
struct SubmissionOptions {
    std::filesystem::path course_root;  //!< the course tree (labs/, tests/ with hidden/, solutions/ if any)
    std::filesystem::path build_dir;    //!< its Ninja build, where test_<lab> was built
    std::filesystem::path work_dir;     //!< this job's folder (reused between submissions; one per parallel job)
    std::string lab;                    //!< e.g. "01_halfedge"
    bool asan = false;                  //!< also build and run with AddressSanitizer + UBSan (ungraded item)
    bool build_course = true;           //!< first bring test_<lab> of the course build up to date
    double compile_timeout_s = 120;     //!< per student file
    std::filesystem::path forbidden;    //!< the forbidden-calls list (default: labs/<lab>/forbidden.txt)
    //! Wall-clock cap of the whole submission (compiles, checks, tests): past it nothing more starts and what runs
    //! is killed; unfinished tests score 0 and the report says so. 0: no cap.
    double max_seconds = 1200;
    //! Root only: grade even when the sandbox (own uid, allow-list file system) cannot be set up, with a loud
    //! "NOT ISOLATED" status. Without it such a grading is refused (fail closed).
    bool allow_unisolated = false;
    RunOptions run;                     //!< limits of the test runs (the sandbox is filled in by the grader)
};

//! How grading a submission went, as a whole. Every status but ok and grader_error scores 0 on every test.
enum class SubmissionStatus {
    ok,
    compile_error,  //!< the student's files did not compile or link
    grader_error,   //!< the grader failed (not the student): grade again
    empty,          //!< none of the lab's files is in the submission
    unreadable,     //!< a zip that cannot be unpacked, or neither a folder nor a zip
    not_found,      //!< no such path
};
const char* to_string(SubmissionStatus s);

//! A call to a function the lab forbids (labs/NN_x/forbidden.txt), found in a compiled student object.
struct ForbiddenCall {
    std::string symbol;  //!< as listed in forbidden.txt
    std::string reason;
    std::string file;  //!< the student file that calls it
    std::string task;  //!< the task (test suite) it zeroes; empty: reported only
    std::string where;  //!< how: the calling function and the way through the student's functions, or "source"
};

//! Everything grading one submission produced.
struct SubmissionReport {
    SubmissionStatus status = SubmissionStatus::grader_error;
    LabReport lab;                      //!< the graded tests, plus the checks (forbidden calls, sanitizers)
    std::vector<std::string> used;      //!< lab files taken from the submission (basename <- path in it)
    std::vector<std::string> stubbed;   //!< lab files the submission lacks: the stub was used
    std::vector<std::string> given;     //!< given files: always the course's copy
    std::vector<std::string> ignored;   //!< other files of the submission, with the reason
    std::string compiler_output;        //!< the compiler's messages (warnings too), paths as the student knows them
    std::vector<ForbiddenCall> forbidden;
    std::vector<std::string> rejected;  //!< problems of the student's objects (symbols, sections, syscalls): score 0
    std::string isolation;  //!< "isolated (...)" or "NOT ISOLATED: reason"
    bool capped = false;    //!< the wall-clock cap was reached
    std::string error;  //!< for grader_error, empty, unreadable, not_found: what went wrong (the status line)
    double seconds = 0;

    //! What a student reads above the tests: status, files used and ignored, compiler messages, checks.
    std::string summary() const;
};

//! Grade `submission` (a folder or a .zip). Never throws for anything the submission does; a grader error
//! (missing course build, unreadable zip) is reported in the result with status grader_error.
SubmissionReport grade_submission(const std::filesystem::path& submission, const SubmissionOptions& opt);

//! The entries of a lab's forbidden.txt: "symbol | reason | task" per line (task optional), '#' comments.
std::vector<ForbiddenCall> read_forbidden_list(const std::filesystem::path& file);

//! Gradescope's results.json schema (https://gradescope-autograders.readthedocs.io/en/latest/specs/), checked:
//! returns the problems found in `text` (empty: valid).
std::vector<std::string> check_gradescope_results(const std::string& text);

}  // namespace geolab::grading
