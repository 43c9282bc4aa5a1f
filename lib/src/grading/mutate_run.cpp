// geolab mutate: build the mutant schemata, grade the baseline, grade every mutant (see grading/mutate.hpp).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <deque>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "geolab/grading/mutate.hpp"
#include "geolab/grading/report.hpp"
#include "geolab/grading/runner.hpp"
#include "text_file.hpp"

namespace geolab::grading::mutate {
namespace fs = std::filesystem;
using detail::read_text;
using detail::write_text;
using detail::split_command;
using detail::find_program;

const char* to_string(Outcome o) {
    switch (o) {
        case Outcome::killed: return "killed";
        case Outcome::timed_out: return "timed out";
        case Outcome::survived: return "survived";
        case Outcome::stillborn: return "stillborn";
        case Outcome::equivalent: return "equivalent";
    }
    return "?";
}

std::size_t MutateReport::count(Outcome o) const {
    return static_cast<std::size_t>(
        std::count_if(results.begin(), results.end(), [&](const MutantResult& r) { return r.outcome == o; }));
}

std::size_t MutateReport::proven_equivalents() const {
    return static_cast<std::size_t>(
        std::count_if(results.begin(), results.end(), [](const MutantResult& r) { return r.outcome == Outcome::equivalent && r.proven; }));
}

double MutateReport::rate() const {
    const double killed = static_cast<double>(count(Outcome::killed) + count(Outcome::timed_out));
    const double denom = killed + static_cast<double>(count(Outcome::survived));
    return denom > 0 ? killed / denom : 0.0;
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

// At most n bytes of s, cut before a UTF-8 continuation byte so that no character is split (a split one makes
// the JSON log line invalid: nlohmann::json refuses to dump it).
std::string utf8_prefix(const std::string& s, std::size_t n) {
    if (s.size() <= n) return s;
    while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;
    return s.substr(0, n);
}

// A trusted command (compiler, linker, git, ninja) with plain limits.
CommandResult run_plain(const std::vector<std::string>& argv, double timeout_s) {
    RunOptions o;
    o.memory_mb = 0;
    o.output_cap = 4 << 20;
    o.file_size_mb = 2048;
    o.sandbox.no_network = false;
    return run_command(argv, timeout_s, o);
}

// How to compile one solution file and link the lab's test program, from the course build.
struct BuildRecipe {
    std::map<std::string, std::vector<std::string>> compile;  // file name -> the command without -o/-c/deps
    std::vector<std::string> link_before, link_after;         // around the lab library's archive
    std::string ccache;
    //! Record and replay (docs/architecture.md): the reference's test program is a performer, linked with the
    //! lab's objects whose boundary functions are renamed for the recorder. Non-empty: apply the same renaming
    //! (objcopy --redefine-syms with this file) to every object compiled here.
    fs::path redefine_syms;

    //! Renames the boundary functions of a freshly compiled object in place (nothing to do without a boundary).
    CommandResult rename_boundary(const fs::path& obj) const {
        if (redefine_syms.empty()) return CommandResult{0, false, "", 0};
        const std::string objcopy = find_program("objcopy");
        if (objcopy.empty()) return CommandResult{1, false, "objcopy not found (apt-get install binutils)", 0};
        return run_plain({objcopy, "--redefine-syms=" + redefine_syms.string(), obj.string()}, 300);
    }

    std::vector<std::string> compile_cmd(const std::string& name, const fs::path& src, const fs::path& obj) const {
        std::vector<std::string> a;
        if (!ccache.empty()) a.push_back(ccache);
        for (const auto& s : compile.at(name)) a.push_back(s);
        for (const char* f : {"-w", "-fdiagnostics-color=never", "-fno-diagnostics-show-caret",
                              "-fdiagnostics-column-unit=byte"})
            a.push_back(f);
        a.push_back("-o");
        a.push_back(obj.string());
        a.push_back("-c");
        a.push_back(src.string());
        return a;
    }
    std::vector<std::string> link_cmd(const std::vector<fs::path>& objects, const fs::path& out) const {
        std::vector<std::string> a = link_before;
        for (const auto& o : objects) a.push_back(o.string());
        for (const auto& s : link_after) a.push_back(s);
        a.push_back("-o");
        a.push_back(out.string());
        return a;
    }
};

BuildRecipe read_recipe(const fs::path& build, const fs::path& src_dir, const std::vector<std::string>& names,
                        const std::string& lab) {
    BuildRecipe r;
    r.ccache = find_program("ccache");
    const fs::path db = build / "compile_commands.json";
    if (!fs::exists(db))
        throw std::runtime_error(db.string() + " not found: configure the course build with CMake first (" + build.string() + ")");
    const auto j = nlohmann::json::parse(read_text(db), nullptr, false);
    if (j.is_discarded()) throw std::runtime_error(db.string() + ": cannot be read");
    for (const auto& e : j) {
        const fs::path file = e.value("file", "");
        if (file.parent_path() != src_dir) continue;
        const std::string name = file.filename().string();
        std::vector<std::string> cmd =
            e.contains("arguments") ? e["arguments"].get<std::vector<std::string>>() : split_command(e.value("command", ""));
        const fs::path dir = e.value("directory", build.string());
        std::vector<std::string> args;
        for (std::size_t i = 0; i < cmd.size(); ++i) {
            const std::string& a = cmd[i];
            if ((a == "-o" || a == "-c" || a == "-MT" || a == "-MF") && i + 1 < cmd.size()) {
                ++i;
                continue;
            }
            if (a == "-MD" || a == "-MMD" || fs::path(a) == file) continue;
            if (a.rfind("-I", 0) == 0 && a.size() > 2 && fs::path(a.substr(2)).is_relative())
                args.push_back("-I" + (dir / a.substr(2)).string());
            else
                args.push_back(a);
        }
        args.push_back("-iquote");
        args.push_back(src_dir.string());
        r.compile[name] = args;
    }
    for (const auto& n : names)
        if (!r.compile.count(n))
            throw std::runtime_error(db.string() + " has no compile command for " + (src_dir / n).string() +
                                     " (re-run cmake on the build)");
    // The link command of the reference's test program: ninja's last command for it.
    const std::string ninja = find_program("ninja");
    if (ninja.empty()) throw std::runtime_error("ninja not found: geolab mutate needs the course's Ninja build");
    const std::string target = "test_" + lab + "_solution";
    CommandResult c = run_plain({ninja, "-C", build.string(), "-t", "commands", target}, 120);
    if (c.exit_code != 0) throw std::runtime_error("cannot read the link command of " + target + ": " + c.output);
    std::istringstream lines(c.output);
    std::string line, last;
    while (std::getline(lines, line))
        if (!trim(line).empty()) last = line;
    const std::string archive = "liblab_" + lab.substr(0, 2) + "_sol.a";
    const std::string performer_archive = "liblab_" + lab.substr(0, 2) + "_sol_performer.a";
    bool seen = false;
    auto args = split_command(last);
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string a = args[i];
        if (a == ":" || a == "&&") continue;
        if (a == "-o" && i + 1 < args.size()) {
            ++i;
            continue;
        }
        if (fs::path(a).filename() == archive || fs::path(a).filename() == performer_archive) {
            if (fs::path(a).filename() == performer_archive) r.redefine_syms = build / "boundary" / lab / "student.syms";
            seen = true;
            continue;
        }
        if (!a.empty() && a[0] != '-' && fs::path(a).is_relative() && fs::exists(build / a)) a = (build / a).string();
        (seen ? r.link_after : r.link_before).push_back(a);
    }
    if (!seen) throw std::runtime_error("the link command of " + target + " does not use " + archive + ": " + last);
    if (!r.link_before.empty() && fs::path(r.link_before[0]).is_relative()) {
        const std::string p = find_program(r.link_before[0]);
        if (!p.empty()) r.link_before[0] = p;
    }
    return r;
}

// The first error line of a compiler's output (for the report; cut to 300 bytes, then made valid UTF-8 again:
// compilers quote with ‘ ’).
std::string first_error(const std::string& out) {
    std::istringstream in(out);
    std::string line;
    while (std::getline(in, line))
        if (line.find("error") != std::string::npos) return valid_utf8(utf8_prefix(trim(line), 300));
    return valid_utf8(utf8_prefix(trim(out), 300));
}

// Every file of a folder with its content: what "restored" is checked against.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> s;
    if (!fs::is_directory(dir)) return s;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) s[e.path().string()] = read_text(e.path());
    return s;
}

// What the baseline did in one test.
struct Baseline {
    TestInfo info;
    bool passed = false;
    Status status = Status::error;
    double seconds = 0;
};

std::string fmt_duration(double s) {
    char buf[64];
    if (s < 60) std::snprintf(buf, sizeof buf, "%.1f s", s);
    else std::snprintf(buf, sizeof buf, "%d min %02d s", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
    return buf;
}

nlohmann::json result_json(const MutantResult& r) {
    return {{"key", r.mutant.key()},       {"id", r.mutant.id},           {"file", r.mutant.file},
            {"line", r.mutant.line},       {"col", r.mutant.col},         {"kind", r.mutant.kind},
            {"original", r.mutant.original}, {"mutated", r.mutant.mutated}, {"outcome", to_string(r.outcome)},
            {"mode", r.mode},              {"detail", r.detail},          {"tests_run", r.tests_run},
            {"anchor", r.anchor},          {"proven", r.proven},
            {"seconds", std::round(r.seconds * 1000) / 1000}};
}

// The schema cache (schema/STEM.excluded): which of a file's mutants its schema had to leave out, and whether the
// schema was relaxed, for the schema text (all mutants in) and the compile command of `key`.
struct SchemaCache {
    bool relax = false;
    std::set<int> excluded;
};
std::string schema_cache_key(const std::string& schema_text, const std::vector<std::string>& command) {
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a, 64 bits
    auto add = [&](const std::string& s) {
        for (unsigned char c : s) {
            h ^= c;
            h *= 1099511628211ull;
        }
        h ^= 0xff;
        h *= 1099511628211ull;
    };
    add("geolab-mutate-schema-1");
    add(schema_text);
    for (const auto& a : command) add(a);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}
std::optional<SchemaCache> read_schema_cache(const fs::path& file, const std::string& key) {
    if (!fs::exists(file)) return std::nullopt;
    std::istringstream in(read_text(file));
    std::string k;
    int relax = 0;
    if (!(in >> k >> relax) || k != key) return std::nullopt;
    SchemaCache c;
    c.relax = relax != 0;
    for (int id; in >> id;) c.excluded.insert(id);
    return c;
}
void write_schema_cache(const fs::path& file, const std::string& key, const SchemaCache& c) {
    std::string text = key + " " + (c.relax ? "1" : "0") + "\n";
    for (int id : c.excluded) text += std::to_string(id) + "\n";
    write_text(file, text);
}

Outcome outcome_from(const std::string& s) {
    for (Outcome o : {Outcome::killed, Outcome::timed_out, Outcome::survived, Outcome::stillborn, Outcome::equivalent})
        if (s == to_string(o)) return o;
    throw std::runtime_error("unknown outcome '" + s + "'");
}

}  // namespace

std::string anchor(const std::string& text, const Mutant& m) {
    std::size_t a = std::min(m.offset, text.size());
    while (a > 0 && text[a - 1] != '\n') --a;
    std::size_t b = text.find('\n', a);
    if (b == std::string::npos) b = text.size();
    std::size_t first = a;
    while (first < b && (text[first] == ' ' || text[first] == '\t')) ++first;
    std::size_t last = b;
    while (last > first && std::isspace(static_cast<unsigned char>(text[last - 1]))) --last;
    std::uint32_t h = 2166136261u;  // FNV-1a
    for (std::size_t i = first; i < last; ++i) {
        h ^= static_cast<unsigned char>(text[i]);
        h *= 16777619u;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%08x+%zu", h, m.offset - first + 1);
    return buf;
}

std::string Equivalent::key() const {
    return file + ":" + std::to_string(line) + ":" + std::to_string(col) + " | " + original + " -> " + mutated;
}

std::vector<Equivalent> read_equivalents(const fs::path& file) {
    std::vector<Equivalent> out;
    if (!fs::exists(file)) return out;
    std::istringstream in(read_text(file));
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        const std::string t = trim(line);
        if (t.empty() || t[0] == '#') continue;
        auto bad = [&](const std::string& why) {
            return std::runtime_error(file.string() + ":" + std::to_string(n) + ": " + why);
        };
        // file:line:col | original -> mutated | [anchor |] reason
        std::vector<std::string> fields;
        for (std::size_t p = 0;;) {
            const auto q = t.find(" | ", p);
            if (q == std::string::npos || fields.size() == 3) {
                fields.push_back(trim(t.substr(p)));
                break;
            }
            fields.push_back(trim(t.substr(p, q - p)));
            p = q + 3;
        }
        const std::regex where(R"((.+):(\d+):(\d+))"), change(R"((.+) -> (.+))"), anch(R"([0-9a-f]{8}\+\d+)");
        std::smatch w, c;
        if (fields.size() < 3 || !std::regex_match(fields[0], w, where) || !std::regex_match(fields[1], c, change))
            throw bad("expected 'file:line:col | original -> mutated | anchor | reason' (the report's survivor line and a reason)");
        Equivalent e;
        e.file = w[1];
        e.line = std::stoi(w[2]);
        e.col = std::stoi(w[3]);
        e.original = trim(c[1]);
        e.mutated = trim(c[2]);
        e.entry_line = n;
        if (fields.size() == 4 && std::regex_match(fields[2], anch)) {
            e.anchor = fields[2];
            e.reason = fields[3];
        } else {  // the old format: the reason is everything after the change
            const auto p1 = t.find(" | "), p2 = t.find(" | ", p1 + 3);
            e.reason = trim(t.substr(p2 + 3));
        }
        if (e.reason.empty()) throw bad("the reason is missing");
        out.push_back(std::move(e));
    }
    return out;
}

std::vector<int> match_equivalents(const std::vector<Equivalent>& entries, const std::vector<Mutant>& mutants,
                                   const std::map<std::string, std::string>& texts) {
    std::vector<int> out(entries.size(), -1);
    std::map<std::string, std::vector<int>> by_change;  // file | original -> mutated: candidates
    for (std::size_t i = 0; i < mutants.size(); ++i)
        by_change[mutants[i].file + " | " + mutants[i].original + " -> " + mutants[i].mutated].push_back(static_cast<int>(i));
    for (std::size_t k = 0; k < entries.size(); ++k) {
        const Equivalent& e = entries[k];
        auto it = by_change.find(e.file + " | " + e.original + " -> " + e.mutated);
        if (it == by_change.end()) continue;
        const auto text = texts.find(e.file);
        int best = -1, best_dist = 0;
        for (int i : it->second) {
            const Mutant& m = mutants[static_cast<std::size_t>(i)];
            if (e.anchor.empty() ? (m.line != e.line || m.col != e.col)
                                 : (text == texts.end() || anchor(text->second, m) != e.anchor))
                continue;
            const int dist = std::abs(m.line - e.line);
            if (best < 0 || dist < best_dist) best = i, best_dist = dist;
        }
        out[k] = best;
    }
    return out;
}

MutateReport run_mutate(const MutateOptions& opt) {
    const auto t_start = Clock::now();
    auto say = [&](const std::string& s) {
        if (!opt.quiet && opt.progress) opt.progress(s);
    };
    MutateReport rep;
    rep.lab = opt.lab;
    const fs::path source = fs::absolute(opt.source), build = fs::absolute(opt.build);
    const fs::path lab_dir = source / "solutions" / opt.lab, src_dir = lab_dir / "src";
    if (!fs::is_directory(src_dir)) throw std::runtime_error(src_dir.string() + ": no such folder (a tree with solutions/ is needed)");

    // 0. solutions/ must be committed: the run must never be mistaken for (or mix with) an edit in progress.
    if (const std::string git = find_program("git"); !git.empty()) {
        CommandResult g = run_plain({git, "-C", source.string(), "status", "--porcelain", "--", lab_dir.string()}, 60);
        if (g.exit_code == 0 && !trim(g.output).empty())
            throw std::runtime_error("solutions/" + opt.lab + " has uncommitted changes; commit or stash them first:\n" +
                                     trim(g.output));
    }
    const auto before = snapshot(lab_dir);

    // 1. The sites.
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(src_dir))
        if (e.is_regular_file() && e.path().extension() == ".cpp") names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    if (names.empty()) throw std::runtime_error(src_dir.string() + " has no .cpp files");
    Vocabulary vocab = Vocabulary::standard();
    for (const fs::path& inc : {source / "labs" / opt.lab / "include", source / "lib" / "include"})
        if (fs::is_directory(inc))
            for (const auto& e : fs::recursive_directory_iterator(inc))
                if (e.is_regular_file()) vocab.scan(read_text(e.path()));
    std::vector<std::string> texts;
    for (const auto& n : names) {
        texts.push_back(read_text(src_dir / n));
        vocab.scan(texts.back());
    }
    std::vector<SourceFile> files;
    int next_id = 0;
    // the mutants this run considers: array bounds only when asked for (see Mutant::array_bound)
    auto considered = [&](const Mutant& m) { return !m.array_bound || opt.array_bounds; };
    for (std::size_t f = 0; f < names.size(); ++f) {
        files.emplace_back("src/" + names[f], texts[f], vocab, next_id);
        next_id += static_cast<int>(files.back().mutants().size());
        for (const auto& m : files.back().mutants()) ++(considered(m) ? rep.total_mutants : rep.array_bound_mutants);
    }
    std::vector<Mutant> chosen;
    {
        // --only FILE[:LINE[-LAST]][,...]
        struct Only {
            std::string file;
            int line = 0, last = 0;  // line 0: every line
        };
        std::vector<Only> only;
        const std::regex lines(R"((.+):(\d+)(?:-(\d+))?)");
        for (std::size_t p = 0; !opt.only.empty() && p <= opt.only.size();) {
            const std::size_t q = std::min(opt.only.find(',', p), opt.only.size());
            const std::string item = trim(opt.only.substr(p, q - p));
            std::smatch mt;
            if (std::regex_match(item, mt, lines))
                only.push_back({mt[1], std::stoi(mt[2]), mt[3].matched ? std::stoi(mt[3]) : std::stoi(mt[2])});
            else if (!item.empty())
                only.push_back({item, 0, 0});
            p = q + 1;
        }
        std::set<int> taken;
        for (const auto& [file, line, last] : only) {
            bool matched = false;
            for (const auto& f : files) {
                if (f.file() != file && f.file() != "src/" + file && fs::path(f.file()).filename() != file &&
                    "solutions/" + opt.lab + "/" + f.file() != file)
                    continue;
                matched = true;
                bool any = false;
                for (const auto& m : f.mutants())
                    if (considered(m) && (line == 0 || (m.line >= line && m.line <= last))) {
                        any = true;
                        if (taken.insert(m.id).second) chosen.push_back(m);
                    }
                if (!any)
                    throw std::runtime_error("--only " + file + ":" + std::to_string(line) +
                                             (last != line ? "-" + std::to_string(last) : "") + ": no mutant there");
            }
            if (!matched) throw std::runtime_error("--only " + file + ": no such file in " + src_dir.string());
        }
        if (only.empty())
            for (const auto& f : files)
                for (const auto& m : f.mutants())
                    if (considered(m)) chosen.push_back(m);
        std::sort(chosen.begin(), chosen.end(), [](const Mutant& a, const Mutant& b) { return a.id < b.id; });
    }
    {
        std::set<std::pair<std::string, int>> sites;
        for (const auto& m : chosen) sites.insert({m.file, static_cast<int>(m.offset)});
        rep.sites = sites.size();
    }
    if (opt.max > 0 && chosen.size() > opt.max) {
        std::mt19937_64 rng(opt.seed);
        for (std::size_t i = 0; i < opt.max; ++i) {  // Fisher-Yates, the first `max` positions
            const std::size_t j = i + static_cast<std::size_t>(rng() % (chosen.size() - i));
            std::swap(chosen[i], chosen[j]);
        }
        chosen.resize(opt.max);
        std::sort(chosen.begin(), chosen.end(), [](const Mutant& a, const Mutant& b) { return a.id < b.id; });
    }

    // 2. Equivalents (reviewed by an instructor): matched by their anchor (the line's text and the column in
    //    it), so that they survive lines moving above them; and what the log already holds.
    std::map<std::string, std::string> equivalent;  // mutant key (today's line and column) -> reason
    {
        const auto entries = read_equivalents(lab_dir / "equivalent-mutants.txt");
        std::vector<Mutant> all;
        std::map<std::string, std::string> by_file;
        for (std::size_t f = 0; f < files.size(); ++f) {
            by_file[files[f].file()] = files[f].text();
            for (const auto& m : files[f].mutants()) all.push_back(m);
        }
        const auto match = match_equivalents(entries, all, by_file);
        for (std::size_t k = 0; k < entries.size(); ++k) {
            if (match[k] < 0) rep.stale_equivalents.push_back(entries[k].key());
            else equivalent[all[static_cast<std::size_t>(match[k])].key()] = entries[k].reason;
        }
    }
    std::map<std::string, std::string> text_of;  // file -> its text (for the anchors)
    for (const auto& f : files) text_of[f.file()] = f.text();
    std::map<std::string, nlohmann::json> logged;
    if (opt.resume && !opt.log.empty() && fs::exists(opt.log)) {
        std::istringstream in(read_text(opt.log));
        std::string line;
        while (std::getline(in, line)) {
            auto j = nlohmann::json::parse(line, nullptr, false);
            if (!j.is_discarded() && j.contains("key") && j.contains("outcome")) logged[j["key"]] = j;
        }
    }
    std::vector<MutantResult> done;
    std::vector<Mutant> todo;
    for (const auto& m : chosen) {
        auto it = logged.find(m.key());
        // --rerun-survivors: a survivor of the logged run is graded again (tests were added since); its new line
        // in the log replaces the old one on the next --resume
        if (it == logged.end() || (opt.rerun_survivors && it->second.value("outcome", "") == "survived")) {
            todo.push_back(m);
            continue;
        }
        MutantResult r;
        r.mutant = m;
        r.anchor = anchor(text_of.at(m.file), m);
        r.outcome = outcome_from(it->second.value("outcome", ""));
        r.mode = "log";
        r.detail = it->second.value("detail", "");
        r.tests_run = it->second.value("tests_run", 0);
        r.seconds = it->second.value("seconds", 0.0);
        r.proven = r.outcome == Outcome::equivalent && it->second.value("proven", false);
        // The equivalent list may have been reviewed since the log was written: today's list decides (a proven
        // equivalent stays one).
        if (r.outcome == Outcome::equivalent && !r.proven && !equivalent.count(m.key())) r.outcome = Outcome::survived;
        if (r.outcome == Outcome::survived && equivalent.count(m.key())) {
            r.outcome = Outcome::equivalent;
            r.detail = equivalent[m.key()];
        }
        done.push_back(r);
    }
    if (!opt.log.empty() && !opt.resume) write_text(opt.log, "");
    std::mutex out_mutex;
    auto record = [&](MutantResult r) {  // the log line, as soon as a mutant is decided
        std::lock_guard lock(out_mutex);
        r.anchor = anchor(text_of.at(r.mutant.file), r.mutant);
        if (r.outcome == Outcome::survived && equivalent.count(r.mutant.key())) {
            r.outcome = Outcome::equivalent;
            r.detail = equivalent[r.mutant.key()];
        } else if ((r.outcome == Outcome::killed || r.outcome == Outcome::timed_out) && equivalent.count(r.mutant.key())) {
            rep.killed_equivalents.push_back(r.mutant.key());
        }
        if (!opt.log.empty()) {
            std::ofstream f(opt.log, std::ios::app);
            f << result_json(r).dump() << "\n";
        }
        done.push_back(std::move(r));
    };
    say("mutate " + opt.lab + ": " + std::to_string(rep.total_mutants) + " mutants in " + std::to_string(files.size()) +
        " files; running " + std::to_string(todo.size()) + (done.empty() ? "" : " (" + std::to_string(done.size()) + " from the log)"));

    // 3. The schemata: one object per file with every chosen mutant of it; sites that do not compile in a
    //    schema are rebuilt alone.
    const auto t_build = Clock::now();
    const fs::path scratch = build / "mutate" / opt.lab;
    fs::create_directories(scratch / "schema");
    fs::create_directories(scratch / "bin");
    const BuildRecipe recipe = read_recipe(build, src_dir, names, opt.lab);
    std::set<int> rebuild_ids;
    std::map<std::string, std::set<int>> schema_ids;  // file -> ids compiled into its schema
    std::map<std::string, std::set<int>> relax_ids;  // file -> ids that need a relaxed schema
    // Every mutant of a file goes into its schema, whatever the sample: the schema source is then the same for
    // every run of the same code (samples, --only, --resume, full runs), so ccache compiles it once.
    std::set<int> todo_ids;
    for (const auto& m : todo) todo_ids.insert(m.id);
    for (const auto& f : files)
        for (const auto& m : f.mutants()) {
            if (m.schema_ok || m.needs_relax) schema_ids[m.file].insert(m.id);
            else if (todo_ids.count(m.id)) rebuild_ids.insert(m.id);
            if (m.needs_relax) relax_ids[m.file].insert(m.id);
        }
    std::vector<fs::path> schema_objects(files.size());
    {
        std::atomic<std::size_t> next{0};
        std::vector<std::string> errors(files.size());
        std::mutex rebuild_mutex;
        auto worker = [&] {
            for (std::size_t f; (f = next++) < files.size();) {
                const SourceFile& file = files[f];
                std::set<int> ids = schema_ids.at(file.file());
                const std::set<int>& relaxed = relax_ids[file.file()];
                bool relax = !relaxed.empty();
                const std::string stem = fs::path(file.file()).stem().string();
                const fs::path src = scratch / "schema" / (stem + ".cpp"), obj = scratch / "schema" / (stem + ".o");
                const std::set<int> all_ids = ids;
                auto unrelax = [&] {  // constexpr is needed after all: the relaxed mutants are rebuilt alone
                    relax = false;
                    std::lock_guard lock(rebuild_mutex);
                    for (int id : relaxed)
                        if (ids.erase(id)) rebuild_ids.insert(id);
                };
                // The compiles that failed last time are not repeated (ccache keeps successes only): the cache
                // names the sites left out of the schema of the same text with the same command.
                const fs::path cache_file = scratch / "schema" / (stem + ".excluded");
                const std::string cache_key = schema_cache_key(file.schema(ids, nullptr, relax), recipe.compile_cmd(names[f], src, obj));
                if (const auto cached = read_schema_cache(cache_file, cache_key)) {
                    if (!cached->relax && relax) unrelax();
                    std::lock_guard lock(rebuild_mutex);
                    for (int id : cached->excluded)
                        if (ids.erase(id)) rebuild_ids.insert(id);
                }
                for (int attempt = 0;; ++attempt) {
                    if (relax && attempt == 30) unrelax();
                    std::vector<SourceFile::Span> spans;
                    write_text(src, file.schema(ids, &spans, relax));
                    CommandResult c = run_plain(recipe.compile_cmd(names[f], src, obj), 1800);
                    if (c.exit_code == 0) c = recipe.rename_boundary(obj);
                    if (c.exit_code == 0) {
                        std::set<int> excluded;
                        std::set_difference(all_ids.begin(), all_ids.end(), ids.begin(), ids.end(),
                                            std::inserter(excluded, excluded.end()));
                        write_schema_cache(cache_file, cache_key, {relax, excluded});
                        break;
                    }
                    // kept for the curious: which sites a schema could not hold, and why
                    write_text(scratch / "schema" / (stem + ".attempt" + std::to_string(attempt) + ".log"), c.output);
                    write_text(scratch / "schema" / (stem + ".attempt" + std::to_string(attempt) + ".cpp"), read_text(src));
                    if (ids.empty() || attempt >= 40) {
                        errors[f] = "the reference " + file.file() + " does not compile as a schema:\n" + c.output.substr(0, 4000);
                        break;
                    }
                    // Map the errors back to the mutants whose text is there.
                    std::set<int> bad;
                    const std::regex where(std::regex_replace(src.filename().string(), std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
                                           R"(:(\d+):(\d+):)");
                    std::istringstream lines(c.output);
                    std::string line;
                    while (std::getline(lines, line)) {
                        if (line.find("error") == std::string::npos && line.find("sorry") == std::string::npos &&
                            line.find("required from") == std::string::npos &&
                            line.find("in 'constexpr' expansion") == std::string::npos && line.find("in constexpr") == std::string::npos)
                            continue;
                        for (std::sregex_iterator it(line.begin(), line.end(), where), end; it != end; ++it) {
                            const int l = std::stoi((*it)[1]), col = std::stoi((*it)[2]);
                            std::set<int> exact, on_line;
                            for (const auto& s : spans) {
                                if (s.line != l || !ids.count(s.id)) continue;
                                on_line.insert(s.id);
                                if (col >= s.col_first && col <= s.col_last) exact.insert(s.id);
                            }
                            if (exact.empty() && on_line.empty()) {
                                // no site on the error's line (a use of a constant the site defines): the
                                // nearest line above with sites, within 12 lines
                                int best = 0;
                                for (const auto& s : spans)
                                    if (ids.count(s.id) && s.line <= l && s.line >= l - 12) best = std::max(best, s.line);
                                for (const auto& s : spans)
                                    if (ids.count(s.id) && s.line == best) on_line.insert(s.id);
                            }
                            for (int id : exact.empty() ? on_line : exact) bad.insert(id);
                        }
                    }
                    if (bad.empty() && relax) {  // nothing attributable: first try without relaxing constexpr
                        unrelax();
                        continue;
                    }
                    if (bad.empty()) bad = ids;  // nothing attributable: this file's mutants are rebuilt alone
                    for (int id : bad) ids.erase(id);
                    std::lock_guard lock(rebuild_mutex);
                    rebuild_ids.insert(bad.begin(), bad.end());
                }
                schema_ids.at(file.file()) = ids;  // distinct keys per worker: no two workers touch one entry
                schema_objects[f] = obj;
            }
        };
        // the maps must hold every key before the workers start (no insertion while they run)
        for (const auto& f : files) {
            schema_ids[f.file()];
            relax_ids[f.file()];
        }
        std::vector<std::thread> pool;
        for (int j = 0; j < std::max(1, std::min<int>(opt.jobs, static_cast<int>(files.size()))); ++j) pool.emplace_back(worker);
        for (auto& t : pool) t.join();
        for (const auto& e : errors)
            if (!e.empty()) throw std::runtime_error(e);
    }
    const fs::path program = scratch / "bin" / ("test_" + opt.lab + "_schema");
    {
        CommandResult l = run_plain(recipe.link_cmd(schema_objects, program), 600);
        if (l.exit_code != 0) throw std::runtime_error("linking the schema program failed:\n" + l.output.substr(0, 4000));
    }
    // Mutants whose mutated expression does not type-check, or changes its type: the schema says so at start-up.
    std::set<int> stillborn_ids;
    RunOptions run;
    run.jobs = 1;
    run.output_cap = 256 << 10;
    run.sandbox.no_network = false;  // the reference's own mutants: no untrusted code, and a namespace costs time
    {
        const fs::path report = scratch / "schema-report.txt";
        fs::remove(report);
        fs::remove(scratch / "tables.txt");
        RunOptions probe = run;
        probe.env.push_back("GEOLAB_MUTANT_REPORT=" + report.string());
        probe.env.push_back("GEOLAB_MUTANT_TABLES=" + (scratch / "tables.txt").string());
        (void)list_tests(program, probe);
        if (fs::exists(report)) {
            std::istringstream in(read_text(report));
            int id;
            std::string what;
            while (in >> id >> what) {
                if (what == "stillborn") stillborn_ids.insert(id);
                else rebuild_ids.insert(id);
            }
        }
    }
    rep.build_seconds = since(t_build);

    // 4. The baseline: the schema program with no mutant selected, every test.
    const auto t_base = Clock::now();
    const std::vector<TestInfo> tests = list_tests(program, run);
    std::vector<Baseline> base(tests.size());
    std::vector<std::set<int>> covers(tests.size());  // per test: the mutants whose site it reaches
    std::vector<std::set<int>> covers_later(tests.size());  // ... past its file's start-up (see started())
    fs::remove_all(scratch / "coverage");
    fs::create_directories(scratch / "coverage");
    {
        std::atomic<std::size_t> next{0};
        auto worker = [&] {
            for (std::size_t i; (i = next++) < tests.size();) {
                RunOptions o = run;
                const fs::path cov = scratch / "coverage" / (std::to_string(i) + ".txt");
                o.env.push_back("GEOLAB_MUTANT_COVERAGE=" + cov.string());
                TestResult r = run_test(program, tests[i], o);
                if (r.status != Status::passed) {  // once more: a busy machine can time a test out once
                    fs::remove(cov);
                    r = run_test(program, tests[i], o);
                }
                base[i] = {tests[i], r.status == Status::passed, r.status, r.seconds};
                if (fs::exists(cov)) {  // k: reached past its file's start-up; -1 - k: during it
                    std::istringstream in(read_text(cov));
                    for (long v; in >> v;) {
                        const int id = static_cast<int>(v < 0 ? -1 - v : v);
                        covers[i].insert(id);
                        if (v >= 0) covers_later[i].insert(id);
                    }
                }
            }
        };
        std::vector<std::thread> pool;
        for (int j = 0; j < std::max(1, opt.jobs); ++j) pool.emplace_back(worker);
        for (auto& t : pool) t.join();
    }
    rep.baseline_tests = tests.size();
    for (const auto& b : base) {
        rep.baseline_max += b.info.points;
        if (b.passed) rep.baseline_score += b.info.points;
    }
    rep.baseline_seconds = since(t_base);
    {
        std::size_t failing = 0;
        std::string names;
        for (const auto& b : base)
            if (!b.passed) {
                ++failing;
                names += std::string(names.empty() ? "" : ", ") + "'" + b.info.name + "' (" + to_string(b.status) + ")";
            }
        say("baseline: " + std::to_string(tests.size()) + " tests in " + fmt_duration(rep.baseline_seconds) +
            (failing ? "; WARNING: " + std::to_string(failing) + " fail on the unmutated reference, twice, and take "
                       "no part in the verdicts (the rate is then a lower bound of what the tests kill): " + names
                     : ", all pass") +
            "; build " + fmt_duration(rep.build_seconds) + " (" +
            std::to_string(std::count_if(todo.begin(), todo.end(), [&](const Mutant& m) { return rebuild_ids.count(m.id) > 0; })) +
            " mutants need a rebuild each)");
    }
    // Mutants of constexpr tables: in a relaxed schema the tables are computed at start-up. A mutant whose site
    // the reference reaches only then (in no test past start-up) changes nothing but the tables: when every
    // table comes out byte for byte the same with it selected, it is equivalent, proven (grade() checks).
    const std::string base_tables = fs::exists(scratch / "tables.txt") ? read_text(scratch / "tables.txt") : "";
    std::set<int> table_only;
    {
        std::set<int> reached, later;
        for (std::size_t i = 0; i < tests.size(); ++i) {
            reached.insert(covers[i].begin(), covers[i].end());
            later.insert(covers_later[i].begin(), covers_later[i].end());
        }
        for (const auto& m : todo)
            if (!base_tables.empty() && m.needs_relax && !rebuild_ids.count(m.id) && !stillborn_ids.count(m.id) &&
                reached.count(m.id) && !later.count(m.id))
                table_only.insert(m.id);
    }
    // Cheap tests first.
    std::vector<std::size_t> cheap(tests.size());
    for (std::size_t i = 0; i < cheap.size(); ++i) cheap[i] = i;
    if (opt.order != "listing")
        std::stable_sort(cheap.begin(), cheap.end(), [&](std::size_t a, std::size_t b) { return base[a].seconds < base[b].seconds; });

    // One process per mutant (--geolab-run-seq): its tests run in order in one process, stopping at the first
    // failure, which is then confirmed in a process of its own as grading runs it. Only when the baseline
    // passes every test in one such process too (no test depends on running alone).
    auto short_limit = [&](std::size_t i) {
        const double limit = tests[i].timeout_s > 0 ? tests[i].timeout_s : run.timeout_s;
        return std::min(limit, opt.timeout_factor * base[i].seconds + 2.0);
    };
    struct SeqVerdict {
        bool passed = false;
        std::string message;
    };
    // Runs `order` (test indices) in one process of `prog`; the verdicts of the tests that ended, in order.
    auto run_seq = [&](const fs::path& prog, const std::vector<std::size_t>& order, const RunOptions& o,
                       const fs::path& dir) {
        fs::create_directories(dir);
        const fs::path list = dir / "seq.txt", out = dir / "seq.out";
        std::string text;
        double total = 5;
        for (std::size_t i : order) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.3f\t", short_limit(i));
            text += buf + tests[i].name + "\n";
            total += short_limit(i);
        }
        write_text(list, text);
        fs::remove(out);
        RunOptions so = o;
        so.output_cap = 16 << 20;
        (void)run_command({prog.string(), "--geolab-run-seq", list.string(), out.string()}, total, so);
        std::vector<SeqVerdict> verdicts;
        if (!fs::exists(out)) return verdicts;
        std::istringstream in(read_text(out));
        for (std::string line; std::getline(in, line);) {
            const auto j = nlohmann::json::parse(line, nullptr, false);
            if (j.is_discarded() || !j.is_object()) break;
            SeqVerdict v;
            v.passed = j.value("status", "") == "passed";
            if (j.contains("messages") && j["messages"].is_array() && !j["messages"].empty() && j["messages"][0].is_string())
                v.message = j["messages"][0].get<std::string>();
            verdicts.push_back(v);
        }
        return verdicts;
    };
    bool seq_mode = !opt.full;
    for (const auto& b : base) seq_mode = seq_mode && b.passed;
    if (seq_mode) {
        const auto v = run_seq(program, cheap, run, scratch / "baseline-seq");
        seq_mode = v.size() == cheap.size() && std::all_of(v.begin(), v.end(), [](const SeqVerdict& x) { return x.passed; });
        if (!seq_mode) say("note: the baseline does not pass its tests in one process: one process per test");
    }

    // 5. The mutants, `jobs` at a time.
    std::map<std::string, std::size_t> last_killer;  // per file: the test that killed its latest mutant
    std::vector<int> kills(tests.size(), 0);         // per test: the mutants it killed so far
    std::atomic<std::size_t> next{0}, finished{0};
    std::atomic<std::size_t> tests_run{0};
    std::map<int, const SourceFile*> file_of;
    for (const auto& f : files)
        for (const auto& m : f.mutants()) file_of[m.id] = &f;
    // the schema's mutants first (about 1 s each), the rebuilt ones last (a compile and a link each, and every
    // test): an interrupted run (--resume) has the most verdicts
    std::stable_sort(todo.begin(), todo.end(), [&](const Mutant& a, const Mutant& b) {
        return rebuild_ids.count(a.id) < rebuild_ids.count(b.id);
    });
    const auto t_run = Clock::now();
    auto grade = [&](const Mutant& m, int job) {
        MutantResult r;
        r.mutant = m;
        const auto t0 = Clock::now();
        fs::path prog = program;
        RunOptions o = run;
        if (stillborn_ids.count(m.id)) {
            r.outcome = Outcome::stillborn;
            r.mode = "schema";
            r.detail = "the mutated expression does not type-check";
            return r;
        }
        std::vector<TestInfo> own_tests;
        if (rebuild_ids.count(m.id)) {
            r.mode = "rebuild";
            const SourceFile& f = *file_of.at(m.id);
            const fs::path dir = scratch / ("job" + std::to_string(job));
            fs::create_directories(dir);
            const std::string name = fs::path(f.file()).filename().string();
            const fs::path src = dir / name, obj = dir / (fs::path(name).stem().string() + ".o");
            write_text(src, f.apply(m));
            CommandResult c = run_plain(recipe.compile_cmd(name, src, obj), 1800);
            if (c.exit_code == 0) c = recipe.rename_boundary(obj);
            if (c.exit_code != 0) {
                r.outcome = Outcome::stillborn;
                r.detail = first_error(c.output);
                r.seconds = since(t0);
                return r;
            }
            std::vector<fs::path> objects = schema_objects;
            for (std::size_t k = 0; k < names.size(); ++k)
                if (names[k] == name) objects[k] = obj;
            prog = dir / ("test_" + opt.lab);
            CommandResult l = run_plain(recipe.link_cmd(objects, prog), 600);
            if (l.exit_code != 0) {
                r.outcome = Outcome::stillborn;
                r.detail = "does not link: " + first_error(l.output);
                r.seconds = since(t0);
                return r;
            }
            try {
                own_tests = list_tests(prog, o);
            } catch (const std::exception& e) {
                r.outcome = Outcome::killed;
                r.detail = "the test program cannot list its tests";
                r.seconds = since(t0);
                return r;
            }
            if (own_tests.size() != tests.size()) {
                r.outcome = Outcome::killed;
                r.detail = "the test program lists " + std::to_string(own_tests.size()) + " tests, not " + std::to_string(tests.size());
                r.seconds = since(t0);
                return r;
            }
        } else {
            r.mode = "schema";
            o.env.push_back("GEOLAB_MUTANT=" + std::to_string(m.id));
            if (table_only.count(m.id)) {
                // only the start-up tables can differ: compare them (one start of the program, no test)
                const fs::path dir = scratch / ("job" + std::to_string(job));
                fs::create_directories(dir);
                const fs::path tables = dir / "tables.txt";
                fs::remove(tables);
                RunOptions probe = o;
                probe.env.push_back("GEOLAB_MUTANT_TABLES=" + tables.string());
                const CommandResult c = run_command({prog.string(), "--geolab-list"}, 60, probe);
                if (c.exit_code == 0 && !c.timed_out && fs::exists(tables) && read_text(tables) == base_tables) {
                    r.outcome = Outcome::equivalent;
                    r.mode = "tables";
                    r.proven = true;
                    r.detail = "proven: its code runs only while the program starts, to compute constexpr tables, "
                               "and every table comes out byte for byte the same";
                    r.seconds = since(t0);
                    return r;
                }
            }
        }
        // The order: the test that killed this file's previous mutant first, then by kills so far per second
        // of run time (the likeliest killer per cost first), the cheap ones among equals.
        std::vector<std::size_t> order = cheap;
        if (opt.order == "killer") {
            std::lock_guard lock(out_mutex);
            std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
                return (kills[a] + 0.5) / (base[a].seconds + 0.02) > (kills[b] + 0.5) / (base[b].seconds + 0.02);
            });
            auto k = last_killer.find(m.file);
            if (k != last_killer.end()) {
                order.erase(std::find(order.begin(), order.end(), k->second));
                order.insert(order.begin(), k->second);
            }
        }
        // A test that failed the unmutated reference (twice) tells nothing: under load a timed-out baseline test
        // that passes with a mutant would count as a kill. It takes no part in any verdict.
        order.erase(std::remove_if(order.begin(), order.end(), [&](std::size_t i) { return !base[i].passed; }),
                    order.end());
        // A mutant of the schema is run only against the tests that reach its site (the baseline's coverage).
        if (r.mode == "schema")
            order.erase(std::remove_if(order.begin(), order.end(), [&](std::size_t i) { return !covers[i].count(m.id); }),
                        order.end());
        r.outcome = Outcome::survived;
        if (order.empty()) r.detail = "no test reaches this code";
        std::size_t from = 0;           // where the one-process-per-test loop below starts
        bool at_own_limit = false;      // its first test ended the sequence's process: decide at the test's limit
        if (seq_mode && !order.empty()) {
            const auto v = run_seq(prog, order, o, scratch / ("job" + std::to_string(job)));
            r.tests_run += static_cast<int>(v.size());
            if (v.size() == 1 && !v.back().passed) {
                // the first test of a fresh process: exactly as grading runs it, nothing to confirm
                r.outcome = Outcome::killed;
                r.detail = "'" + tests[order[0]].name + "' failed";
                if (!v.back().message.empty()) r.detail += ": " + valid_utf8(utf8_prefix(v.back().message, 200));
                std::lock_guard lock(out_mutex);
                last_killer[m.file] = order[0];
                ++kills[order[0]];
                from = order.size();
            } else if (!v.empty() && !v.back().passed) {
                from = v.size() - 1;  // a failure after other tests: confirmed alone below
            } else if (v.size() == order.size()) {
                from = order.size();  // all passed: survived
            } else {  // a crash, the time limit, the output cap
                from = v.size();
                at_own_limit = true;
            }
        }
        for (std::size_t pos = from; pos < order.size(); ++pos) {
            const std::size_t i = order[pos];
            TestInfo t = tests[i];
            const double limit = t.timeout_s > 0 ? t.timeout_s : o.timeout_s;
            t.timeout_s = at_own_limit && pos == from ? limit : std::min(limit, opt.timeout_factor * base[i].seconds + 2.0);
            TestResult tr = run_test(prog, t, o);
            ++r.tests_run;
            if (tr.status == Status::timeout && t.timeout_s < limit) {
                // Past the short limit: maybe only a busy machine. Decide at the test's own limit, as grading does.
                t.timeout_s = limit;
                tr = run_test(prog, t, o);
                ++r.tests_run;
            }
            if ((tr.status == Status::passed) == base[i].passed) continue;
            const bool first = r.outcome == Outcome::survived;
            if (first) {
                r.outcome = tr.status == Status::timeout ? Outcome::timed_out : Outcome::killed;
                r.detail = "'" + t.name + "' " + to_string(tr.status);
                if (!tr.messages.empty()) r.detail += ": " + valid_utf8(utf8_prefix(tr.messages.front(), 200));
                std::lock_guard lock(out_mutex);
                last_killer[m.file] = i;
                ++kills[i];
            }
            if (!opt.full) break;
        }
        r.seconds = since(t0);
        return r;
    };
    auto progress_line = [&] {
        std::size_t k = 0, s = 0, t = 0, sb = 0;
        {
            std::lock_guard lock(out_mutex);
            for (const auto& r : done) {
                if (r.mode == "log") continue;
                k += r.outcome == Outcome::killed;
                s += r.outcome == Outcome::survived || r.outcome == Outcome::equivalent;
                t += r.outcome == Outcome::timed_out;
                sb += r.outcome == Outcome::stillborn;
            }
        }
        const std::size_t f = finished.load();
        const double el = since(t_run);
        const double eta = f ? el / static_cast<double>(f) * static_cast<double>(todo.size() - f) : 0;
        return "[" + std::to_string(f) + "/" + std::to_string(todo.size()) + "] killed " + std::to_string(k) +
               ", survived " + std::to_string(s) + ", timed out " + std::to_string(t) + ", stillborn " +
               std::to_string(sb) + "; " + fmt_duration(el) + (f < todo.size() ? ", about " + fmt_duration(eta) + " left" : "");
    };
    {
        auto last_progress = Clock::now();
        std::mutex progress_mutex;
        auto worker = [&](int job) {
            for (std::size_t i; (i = next++) < todo.size();) {
                MutantResult r = grade(todo[i], job);
                tests_run += static_cast<std::size_t>(r.tests_run);
                record(std::move(r));
                ++finished;
                std::lock_guard lock(progress_mutex);
                if (since(last_progress) > 5 || finished == todo.size()) {
                    last_progress = Clock::now();
                    say(progress_line());
                }
            }
        };
        std::vector<std::thread> pool;
        for (int j = 0; j < std::max(1, opt.jobs); ++j) pool.emplace_back(worker, j);
        for (auto& t : pool) t.join();
    }
    std::sort(done.begin(), done.end(), [](const MutantResult& a, const MutantResult& b) { return a.mutant.id < b.mutant.id; });
    rep.results = std::move(done);
    for (const auto& r : rep.results) {
        if (r.mode == "schema") ++rep.schema_mutants;
        if (r.mode == "rebuild") ++rep.rebuilt_mutants;
    }
    rep.tests_run = tests_run;
    rep.seconds = since(t_start);
    // 6. solutions/ is exactly as it was (the run never writes there; this proves it).
    if (snapshot(lab_dir) != before)
        throw std::runtime_error("solutions/" + opt.lab + " changed during the run: check `git status` and restore it");
    return rep;
}

std::string format_report(const MutateReport& rep) {
    std::ostringstream os;
    const std::size_t killed = rep.count(Outcome::killed), timed = rep.count(Outcome::timed_out),
                      survived = rep.count(Outcome::survived), still = rep.count(Outcome::stillborn),
                      equiv = rep.count(Outcome::equivalent);
    os << "geolab mutate " << rep.lab << ": " << rep.results.size() << " mutants";
    if (rep.results.size() != rep.total_mutants) os << " (a sample of " << rep.total_mutants << ")";
    os << " at " << rep.sites << " sites\n";
    if (rep.array_bound_mutants)
        os << "  (" << rep.array_bound_mutants << " mutants of array bounds left out: --array-bounds runs them, each rebuilt alone)\n";
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "  killed      %5zu  (%zu of them by the time limit)\n  survived    %5zu\n  equivalent  %5zu  (%zu reviewed, "
                  "listed in equivalent-mutants.txt; %zu proven: the same constexpr tables)\n  stillborn   %5zu  (do not compile)\n",
                  killed + timed, timed, survived, equiv, equiv - rep.proven_equivalents(), rep.proven_equivalents(), still);
    os << buf;
    std::snprintf(buf, sizeof buf, "  score       %.1f %% of non-equivalent mutants killed (%zu / %zu)\n", 100 * rep.rate(),
                  killed + timed, killed + timed + survived);
    os << buf;
    if (survived) {
        os << "survivors (file:line:col | original -> mutated | anchor): add a test that kills each, or mark it "
              "equivalent (copy the line, add ' | reason')\n";
        for (const auto& r : rep.results)
            if (r.outcome == Outcome::survived)
                os << "  " << r.mutant.key() << (r.anchor.empty() ? "" : " | " + r.anchor)
                   << (r.detail.empty() ? "" : "   [" + r.detail + "]") << "\n";
    }
    if (equiv > rep.proven_equivalents()) {
        os << "equivalent (reviewed):\n";
        for (const auto& r : rep.results)
            if (r.outcome == Outcome::equivalent && !r.proven) os << "  " << r.mutant.key() << " | " << r.detail << "\n";
    }
    if (rep.proven_equivalents()) {
        os << "equivalent (proven: their code runs only at start-up, to compute constexpr tables, which come out byte "
              "for byte the same):\n";
        for (const auto& r : rep.results)
            if (r.outcome == Outcome::equivalent && r.proven) os << "  " << r.mutant.key() << "\n";
    }
    for (const auto& k : rep.killed_equivalents)
        os << "warning: equivalent-mutants.txt lists '" << k << "', but the tests kill it: remove it from the list\n";
    for (const auto& s : rep.stale_equivalents)
        os << "warning: equivalent-mutants.txt lists '" << s << "', which is no mutant of the current code (stale?)\n";
    os << "time: " << fmt_duration(rep.seconds) << " (build " << fmt_duration(rep.build_seconds) << ", baseline "
       << rep.baseline_tests << " tests in " << fmt_duration(rep.baseline_seconds) << "); " << rep.schema_mutants
       << " mutants run from the schema, " << rep.rebuilt_mutants << " rebuilt alone; " << rep.tests_run << " tests run\n";
    return os.str();
}

std::string report_json(const MutateReport& rep) {
    nlohmann::json j;
    j["lab"] = rep.lab;
    j["mutants"] = rep.results.size();
    j["total_mutants"] = rep.total_mutants;
    j["array_bound_mutants_left_out"] = rep.array_bound_mutants;
    j["sites"] = rep.sites;
    j["killed"] = rep.count(Outcome::killed) + rep.count(Outcome::timed_out);
    j["timed_out"] = rep.count(Outcome::timed_out);
    j["survived"] = rep.count(Outcome::survived);
    j["equivalent"] = rep.count(Outcome::equivalent);
    j["proven_equivalent"] = rep.proven_equivalents();
    j["stillborn"] = rep.count(Outcome::stillborn);
    j["rate"] = std::round(rep.rate() * 10000) / 10000;
    j["survivors"] = nlohmann::json::array();
    j["equivalents"] = nlohmann::json::array();
    j["proven_equivalents"] = nlohmann::json::array();
    for (const auto& r : rep.results) {
        if (r.outcome == Outcome::survived) j["survivors"].push_back(r.mutant.key());
        if (r.outcome == Outcome::equivalent && !r.proven) j["equivalents"].push_back(r.mutant.key());
        if (r.outcome == Outcome::equivalent && r.proven) j["proven_equivalents"].push_back(r.mutant.key());
    }
    j["stale_equivalents"] = rep.stale_equivalents;
    j["killed_equivalents"] = rep.killed_equivalents;
    j["seconds"] = std::round(rep.seconds * 10) / 10;
    j["build_seconds"] = std::round(rep.build_seconds * 10) / 10;
    j["baseline_tests"] = rep.baseline_tests;
    j["tests_run"] = rep.tests_run;
    j["schema_mutants"] = rep.schema_mutants;
    j["rebuilt_mutants"] = rep.rebuilt_mutants;
    return j.dump();
}

}  // namespace geolab::grading::mutate
