// geolab gradescope --lab NN --out autograder.zip: the Gradescope autograder of one lab (setup.sh, run_autograder
// and the course tree, hidden tests included); geolab gradescope --validate results.json checks a results file
// against Gradescope's published format.
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

#include "commands.hpp"
#include "geolab/grading/submission.hpp"
#include "geolab/models.hpp"

namespace geolab::cli {
namespace fs = std::filesystem;
namespace {

// The apt packages setup.sh installs: the build's dependencies, by names that Ubuntu 22.04, Ubuntu 24.04 and
// Debian 12 all have (docs/instructor.md says how that was checked). No Eigen, benchmark or peer libraries: the
// autograder builds only geolab and the lab's test program.
constexpr const char* kPackages =
    "build-essential cmake ninja-build pkg-config git unzip zip libglm-dev libglfw3-dev libosmesa6-dev libgl-dev "
    "doctest-dev libstb-dev nlohmann-json3-dev libcli11-dev libeigen3-dev libgmp-dev clang-tools "
    "libfreetype-dev fonts-dejavu-core";

// The shell test that every model file the tests load is in data/models/ (under "$1"); prints the missing ones.
std::string missing_models_check(const std::vector<std::string>& models) {
    std::string list;
    for (const auto& m : models) list += (list.empty() ? "" : " ") + m;
    return "missing_models() {  # the models the tests load, carried by the zip in data/models/\n"
           "  for m in " + (list.empty() ? std::string("''") : list) + "; do\n"
           "    [ -z \"$m\" ] || [ -s \"$1/data/models/$m\" ] || printf ' %s' \"$m\"\n"
           "  done\n"
           "}\n";
}

// setup.sh: runs once when Gradescope builds the image (Ubuntu 22.04 or 24.04, as root) in /autograder/source.
// " judge_<lab>" when the lab grades by record and replay (its judge decides the verdicts; see architecture.md).
std::string judge_target(const std::string& lab) {
    return std::filesystem::exists(bin_dir() / ("judge_" + lab)) ? " judge_" + lab : "";
}

std::string setup_sh(const std::string& lab, const std::vector<std::string>& models) {
    return R"(#!/usr/bin/env bash
# Gradescope image set-up for geolab lab )" + lab + R"(: packages, a check of the models this zip carries, the one-time
# build of the course tree. For Gradescope's Ubuntu 22.04 and 24.04 images (Debian 12 works too).
# AUTOGRADER_ROOT (default /autograder) lets you try the same steps locally; GEOLAB_SKIP_PACKAGES=1 skips apt-get
# (when the packages are installed already) and GEOLAB_CMAKE_ARGS adds arguments to the configure step.
set -euo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
cd "$root/source"
if [ "${GEOLAB_SKIP_PACKAGES:-0}" != 1 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq )" + kPackages + R"( >/dev/null
fi
)" + missing_models_check(models) + R"(missing=$(missing_models "$root/source")
if [ -n "$missing" ]; then
  echo "SETUP ERROR: the autograder zip lacks the model(s)$missing in data/models/ that lab )" + lab + R"('s tests load." >&2
  echo "Write the zip again with 'geolab gradescope' after tools/fetch_models.sh." >&2
  exit 1
fi
# shellcheck disable=SC2086  # GEOLAB_CMAKE_ARGS is a list of arguments
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DGEOLAB_BENCHMARKS=OFF \
  -DGEOLAB_MODELS_DIR="$root/source/data/models" ${GEOLAB_CMAKE_ARGS:-} >/dev/null
cmake --build build --target geolab test_)" + lab + judge_target(lab) + R"(
# The answers stay root-only, whatever else the sandbox manages to do (it also hides them from the tests).
chmod -R go-rwx solutions tests build/CMakeFiles build/bin 2>/dev/null || true
chmod go+x build build/bin
# The lab's judge (record and replay) runs as the sandbox user: it may run it, never read it.
chmod go+x build/bin/judge_* 2>/dev/null || true
)";
}

// run_autograder: runs once per submission, as root, working directory /autograder.
std::string run_autograder(const std::string& lab, const std::vector<std::string>& models) {
    return R"(#!/usr/bin/env bash
# Grade /autograder/submission with geolab; results in /autograder/results/results.json.
# AUTOGRADER_ROOT (default /autograder) and GEOLAB (the geolab program) let you try it locally.
# A set-up error (a model the tests load, or the built grader, missing) is the autograder's fault, not the
# student's: it is reported as such and no results.json is written, so Gradescope shows that the autograder
# failed instead of a score.
set -uo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
geolab=${GEOLAB:-$root/source/build/bin/geolab}
mkdir -p "$root/results"
)" + missing_models_check(models) + R"(missing=$(missing_models "$root/source")
if [ -n "$missing" ] || [ ! -x "$geolab" ]; then
  echo "SETUP ERROR (not a problem with your submission; your instructor has to fix the autograder):"
  [ -z "$missing" ] || echo "  the model(s)$missing that lab )" + lab + R"('s tests load are not in $root/source/data/models/"
  [ -x "$geolab" ] || echo "  the grader $geolab was not built: see what setup.sh printed"
  rm -f "$root/results/results.json"
  exit 1
fi
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

// The model files (e.g. "bunny00.off") the tests of `lab` load, found in the tests' sources: every string literal
// that names a fetched model, and every literal name given to load_model() or model_path(). \throw
// std::runtime_error naming the models that are loaded but not fetched (the zip would lack them).
std::vector<std::string> lab_models(const fs::path& root, const std::string& lab) {
    std::set<std::string> found, missing;
    const std::regex literal(R"re("([A-Za-z0-9_.+-]{1,80})")re"), call(R"re((load_model|model_path)\(\s*"([^"]+)")re");
    const fs::path tests = root / "tests" / lab;
    if (!fs::is_directory(tests)) return {};
    for (const auto& e : fs::recursive_directory_iterator(tests)) {
        const auto ext = e.path().extension();
        if (!e.is_regular_file() || (ext != ".cpp" && ext != ".hpp" && ext != ".h")) continue;
        std::ifstream f(e.path());
        std::stringstream ss;
        ss << f.rdbuf();
        const std::string text = ss.str();
        for (std::sregex_iterator it(text.begin(), text.end(), literal), end; it != end; ++it)
            if (const auto p = model_path((*it)[1].str())) found.insert(p->filename().string());
        for (std::sregex_iterator it(text.begin(), text.end(), call), end; it != end; ++it)
            if (!model_path((*it)[2].str())) missing.insert((*it)[2].str());
    }
    if (!missing.empty()) {
        std::string names;
        for (const auto& m : missing) names += " " + m;
        throw std::runtime_error("lab " + lab + "'s tests load the model(s)" + names + ", which are not in " +
                                 models_dir().string() + ": run tools/fetch_models.sh, then write the zip again");
    }
    return {found.begin(), found.end()};
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
        // The models the tests load travel in the zip: setup.sh fetches nothing.
        const auto models = lab_models(root, lab);
        fs::create_directories(stage / "data" / "models");
        for (const auto& m : models) fs::copy_file(models_dir() / m, stage / "data" / "models" / m);
        write_exec(stage / "setup.sh", setup_sh(lab, models));
        write_exec(stage / "run_autograder", run_autograder(lab, models));
        const fs::path out = fs::absolute(a->out);
        fs::remove(out);
        const std::string cmdline = "cd '" + stage.string() + "' && zip -qr '" + out.string() + "' .";
        const int rc = std::system(cmdline.c_str());
        fs::remove_all(stage);
        if (rc != 0) throw std::runtime_error(out.string() + ": zip failed (is zip installed?)");
        std::string names;
        for (const auto& m : models) names += " " + m;
        std::cout << "Gradescope autograder for lab " << lab << " written to " << out.string() << " with "
                  << models.size() << " model(s)" << (names.empty() ? "" : ":" + names)
                  << " (upload it as the assignment's autograder; setup.sh builds the course, run_autograder grades)\n";
    });
}

}  // namespace geolab::cli
