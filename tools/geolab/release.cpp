// geolab release: the single-source rule. labs/ is generated from solutions/; the student release is a copy of
// the course tree without answers or hidden tests.
#include <iostream>

#include "commands.hpp"
#include "geolab/grading/release.hpp"

namespace geolab::cli {

void add_release(CLI::App& app, int& status) {
    struct Args {
        std::string out, root;
        bool check = false, write_labs = false;
    };
    auto a = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("release", "Generate labs/ from solutions/, check it, or write the student release");
    cmd->add_option("--out", a->out, "Write the student release into this (new or empty) folder");
    cmd->add_flag("--check", a->check, "Only check that labs/ is exactly what the generator makes (CI)");
    cmd->add_flag("--write-labs", a->write_labs, "Regenerate labs/*/src from solutions/ in place");
    cmd->add_option("--root", a->root, "The course tree (default: the one this program was built from)");
    cmd->callback([a, &status] {
        const std::filesystem::path root = a->root.empty() ? source_dir() : std::filesystem::path(a->root);
        if (!std::filesystem::is_directory(root / "solutions"))
            throw std::runtime_error(root.string() + " has no solutions/: releases are made from the instructor's tree");
        if (a->check || a->write_labs) {
            auto diffs = grading::generate_labs(root, a->write_labs);
            for (const auto& d : diffs) std::cout << d.file.string() << ": " << d.reason << "\n";
            if (a->write_labs) {
                std::cout << "labs/ regenerated (" << diffs.size() << " file(s) changed)\n";
            } else {
                std::cout << (diffs.empty() ? "labs/ is exactly what the generator makes from solutions/\n"
                                            : "labs/ differs from solutions/: run 'geolab release --write-labs'\n");
                status = diffs.empty() ? 0 : 1;
            }
        }
        if (!a->out.empty()) {
            auto files = grading::make_release(root, a->out);
            std::cout << "student release written to " << a->out << " (" << files.size() << " files)\n";
        }
        if (!a->check && !a->write_labs && a->out.empty())
            throw std::runtime_error("release: say --check, --write-labs or --out DIR");
    });
}

}  // namespace geolab::cli
