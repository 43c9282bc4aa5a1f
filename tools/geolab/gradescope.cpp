// geolab gradescope --lab NN --out autograder.zip: the Gradescope autograder of one lab (setup.sh, run_autograder
// and the course tree, hidden tests included); geolab gradescope --validate results.json checks a results file
// against Gradescope's published format.
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

#include "commands.hpp"
#include "geolab/grading/submission.hpp"

namespace geolab::cli {
namespace fs = std::filesystem;
namespace {

// setup.sh: runs once when Gradescope builds the image (Ubuntu, as root) in /autograder/source.
std::string setup_sh(const std::string& lab) {
    return R"(#!/usr/bin/env bash
# Gradescope image set-up for geolab lab )" + lab + R"(: packages, models, the one-time build of the course tree.
# AUTOGRADER_ROOT (default /autograder) lets you try the same steps locally.
set -euo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
cd "$root/source"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq build-essential cmake ninja-build pkg-config git unzip zip \
  libglm-dev libglfw3-dev libosmesa6-dev libgl-dev doctest-dev libstb-dev nlohmann-json3-dev libcli11-dev \
  libeigen3-dev clang-tools >/dev/null
tools/fetch_models.sh || echo "continuing without the CGAL models: tests that need them say so"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DGEOLAB_BENCHMARKS=OFF >/dev/null
cmake --build build --target geolab test_)" + lab + R"(
# The answers stay root-only, whatever else the sandbox manages to do (it also hides them from the tests).
chmod -R go-rwx solutions tests build/CMakeFiles build/bin 2>/dev/null || true
chmod go+x build build/bin
)";
}

// run_autograder: runs once per submission, as root, working directory /autograder.
std::string run_autograder(const std::string& lab) {
    return R"(#!/usr/bin/env bash
# Grade /autograder/submission with geolab; results in /autograder/results/results.json.
# AUTOGRADER_ROOT (default /autograder) and GEOLAB (the geolab program) let you try it locally.
set -uo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
geolab=${GEOLAB:-$root/source/build/bin/geolab}
mkdir -p "$root/results"
work=$(mktemp -d)
chmod 711 "$work"  # the tests run as their own uid: they must reach their program (never list the folder)
cp -r "$root/submission" "$work/submission"
# --max-seconds: the whole submission ends (with a results.json) well before Gradescope's own time limit.
"$geolab" grade --submission "$work/submission" --lab )" + lab + R"( --no-course-build --max-seconds 540 \
  --json "$root/results/results.json" --junit "$root/results/junit.xml" --work-dir "$work/grading"
status=$?
rm -rf "$work"
if [ ! -s "$root/results/results.json" ]; then
  printf '{"score": 0, "output": "The autograder failed (status %s); please tell your instructor.", "tests": []}\n' \
    "$status" >"$root/results/results.json"
fi
exit 0
)";
}

void write_exec(const fs::path& p, const std::string& text) {
    std::ofstream f(p);
    f << text;
    f.close();
    if (!f) throw std::runtime_error(p.string() + ": cannot write");
    ::chmod(p.c_str(), 0755);
}

}  // namespace

void add_gradescope(CLI::App& app, int& status) {
    struct Args {
        std::string lab, out, validate;
    };
    auto a = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("gradescope", "Write a lab's Gradescope autograder zip, or validate a results.json");
    cmd->add_option("--lab", a->lab, "The lab: 01, 1 or 01_halfedge");
    cmd->add_option("--out", a->out, "The autograder zip to write (e.g. autograder.zip)");
    cmd->add_option("--validate", a->validate, "Check this results.json against Gradescope's format and exit");
    cmd->callback([a, &status] {
        if (!a->validate.empty()) {
            std::ifstream f(a->validate);
            if (!f) throw std::runtime_error(a->validate + ": cannot read");
            std::stringstream ss;
            ss << f.rdbuf();
            const auto problems = grading::check_gradescope_results(ss.str());
            for (const auto& p : problems) std::cout << a->validate << ": " << p << "\n";
            if (problems.empty()) std::cout << a->validate << ": valid Gradescope results\n";
            status = problems.empty() ? 0 : 1;
            return;
        }
        if (a->lab.empty() || a->out.empty()) throw std::runtime_error("gradescope: say --lab NN --out autograder.zip");
        const std::string lab = resolve_lab(a->lab);
        const fs::path root = source_dir();
        if (!fs::is_directory(root / "solutions"))
            throw std::runtime_error(root.string() + " has no solutions/: the autograder is made from the instructor's tree");
        // Stage: the course tree (without builds, models, git, outputs) plus the two scripts at the root.
        const fs::path stage = fs::temp_directory_path() / ("geolab-gradescope-" + std::to_string(::getpid()));
        fs::remove_all(stage);
        fs::create_directories(stage);
        for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
            const fs::path rel = fs::relative(it->path(), root);
            const std::string first = rel.begin()->string();
            if (first == ".git" || first.rfind("build", 0) == 0 || first == "out" || rel.string().rfind("data/models", 0) == 0) {
                if (it->is_directory()) it.disable_recursion_pending();
                continue;
            }
            if (it->is_directory()) continue;
            if (!it->is_regular_file()) continue;
            fs::create_directories((stage / rel).parent_path());
            fs::copy_file(it->path(), stage / rel);
        }
        write_exec(stage / "setup.sh", setup_sh(lab));
        write_exec(stage / "run_autograder", run_autograder(lab));
        const fs::path out = fs::absolute(a->out);
        fs::remove(out);
        const std::string cmdline = "cd '" + stage.string() + "' && zip -qr '" + out.string() + "' .";
        const int rc = std::system(cmdline.c_str());
        fs::remove_all(stage);
        if (rc != 0) throw std::runtime_error(out.string() + ": zip failed (is zip installed?)");
        std::cout << "Gradescope autograder for lab " << lab << " written to " << out.string()
                  << " (upload it as the assignment's autograder; setup.sh builds the course, run_autograder grades)\n";
    });
}

}  // namespace geolab::cli
