// geolab: the course's one command-line entry.
#include <iostream>

#include "commands.hpp"
#include "geolab/config.hpp"

namespace geolab::cli {

std::vector<std::string> known_labs() {
    std::vector<std::string> labs;
    std::string list = GEOLAB_LAB_LIST;
    for (std::size_t a = 0; a < list.size();) {
        std::size_t b = list.find(',', a);
        if (b == std::string::npos) b = list.size();
        if (b > a) labs.push_back(list.substr(a, b - a));
        a = b + 1;
    }
    return labs;
}

std::string resolve_lab(const std::string& arg) {
    std::string nn = arg.size() == 1 ? "0" + arg : arg.substr(0, 2);
    for (const auto& lab : known_labs())
        if (lab == arg || lab.substr(0, 2) == nn) return lab;
    std::string names;
    for (const auto& lab : known_labs()) names += " " + lab;
    throw CLI::ValidationError("lab", "unknown lab '" + arg + "'; this build has:" + names);
}

std::filesystem::path bin_dir() {
    std::error_code ec;
    auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::current_path() : exe.parent_path();
}

std::filesystem::path source_dir() { return config::source_dir; }

}  // namespace geolab::cli

int main(int argc, char** argv) {
    CLI::App app{"geolab: a curriculum library for geometric modeling (labs, grader, demos)"};
    app.require_subcommand(1);
    int status = 0;
    geolab::cli::add_grade(app, status);
    geolab::cli::add_grade_all(app, status);
    geolab::cli::add_gradescope(app, status);
    geolab::cli::add_release(app, status);
    geolab::cli::add_demo(app, status);
    geolab::cli::add_info(app, status);
    geolab::cli::add_contour(app, status);
    geolab::cli::add_table1(app, status);
    geolab::cli::add_mutate(app, status);
    geolab::cli::add_quadric(app, status);
    geolab::cli::add_blobby(app, status);
    geolab::cli::add_sweep(app, status);
    geolab::cli::add_csg(app, status);
    geolab::cli::add_voxelize(app, status);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::cerr << "geolab: " << e.what() << "\n";
        return 1;
    }
    return status;
}
