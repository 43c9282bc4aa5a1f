// geolab demo NN [args]: run a lab's demo (a window by default; --png / --figures for headless images).
#include <unistd.h>

#include <iostream>

#include "commands.hpp"

namespace geolab::cli {

void add_demo(CLI::App& app, int& status) {
    auto lab = std::make_shared<std::string>();
    auto* cmd = app.add_subcommand("demo", "Run a lab's lecture demo; what follows the lab goes to the demo (--help, --png FILE, --figures DIR)");
    cmd->add_option("lab", *lab, "The lab: 01, 1 or 01_halfedge");
    cmd->prefix_command();
    // No help flag of its own: `geolab demo 01 --help` is the demo's help (its options and window keys).
    cmd->set_help_flag();
    cmd->callback([lab, cmd, &status] {
        const auto rest = cmd->remaining();
        if (lab->empty()) {
            const bool help = !rest.empty() && (rest[0] == "--help" || rest[0] == "-h");
            std::string labs;
            for (const auto& l : known_labs()) labs += " " + l;
            (help ? std::cout : std::cerr) << cmd->help() << "\nLabs:" << labs
                                           << "\n`geolab demo NN --help` shows that demo's options and window keys.\n";
            status = help ? 0 : 1;
            return;
        }
        const std::string name = resolve_lab(*lab);
        const auto program = bin_dir() / ("demo_" + name);
        if (!std::filesystem::exists(program))
            throw std::runtime_error("lab " + name + " has no demo program at " + program.string());
        std::vector<std::string> all{program.string()};
        for (const auto& r : rest) all.push_back(r);
        std::vector<char*> argv;
        for (auto& s : all) argv.push_back(s.data());
        argv.push_back(nullptr);
        std::cout.flush();
        ::execv(argv[0], argv.data());
        throw std::runtime_error("cannot run " + program.string());
    });
}

}  // namespace geolab::cli
