#pragma once
//! \file grading/mutate.hpp
//! Mutation testing of a lab's tests (`geolab mutate NN`): seed one plausible bug at a time into the reference
//! solution's `// BEGIN SOLUTION` ... `// END SOLUTION` blocks and see whether the lab's tests notice.
//!
//! Mutation sites are found by a C++ lexer (comments, string and character literals including raw strings,
//! preprocessor lines and template angle brackets are never mutated), then every mutant of a file is compiled
//! into one object, a *mutant schema*: each site becomes a run-time choice between the original and its
//! mutants, selected by the environment variable GEOLAB_MUTANT (read once). A site whose schema does not
//! compile (a constant expression, for instance) is rebuilt one mutant at a time instead.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace geolab::grading::mutate {

//! What a lexed token is.
enum class TokenKind { identifier, number, string, punct, preprocessor, comment };

//! One token of a C++ source: where it is (byte offset, 1-based line and column) and its text.
struct Token {
    TokenKind kind = TokenKind::punct;
    std::size_t offset = 0, length = 0;
    int line = 1, col = 1;
    std::string text;
};

//! Lex a C++ source into tokens (comments and preprocessor lines included, whitespace dropped). `>>` and
//! `>>=` are single tokens; string literals keep their prefix (u8, L, R"d(...)d" ...).
//! \throw std::runtime_error "NAME:LINE: unterminated ..." for an unterminated comment or literal.
std::vector<Token> lex(const std::string& text, const std::string& name);

//! One mutant: a single edit of one solution file.
struct Mutant {
    int id = 0;                   //!< unique within one run; the value of GEOLAB_MUTANT that selects it
    std::string file;             //!< relative to solutions/NN_name, e.g. "src/qef.cpp"
    int line = 0, col = 0;        //!< of the mutated token
    std::string kind;             //!< relational, equality, arithmetic, logical, negation, unary-minus, constant,
                                  //!< swap, compound, drop-return, drop-break, drop-continue
    std::string original, mutated;  //!< as the report shows them ("(dropped)" for a dropped statement)
    std::size_t offset = 0, length = 0;  //!< the byte range of the file that the mutant replaces ...
    std::string replacement;             //!< ... with this text
    bool schema_ok = true;     //!< false: in a constant context; rebuilt alone unless ...
    bool needs_relax = false;  //!< ... only constexpr makes it so: then it works in a relaxed schema
    //! A constant in an array bound of a declaration ("double a[3]"): a change of type, run only with
    //! MutateOptions::array_bounds (a smaller bound makes the reference's own indexing undefined behaviour, a
    //! larger one changes nothing unless the size is read; each costs a rebuild of its file).
    bool array_bound = false;
    //! "src/qef.cpp:12:5 | < -> <=": how equivalent-mutants.txt and the log name a mutant.
    std::string key() const;
};

//! Names the lexer must know: templates (so `name<` opens template arguments) and the identifiers of the
//! lab's API (an identifier swap such as next -> prev is made only if the other name exists).
struct Vocabulary {
    std::set<std::string> templates;
    std::set<std::string> identifiers;
    //! Add the template names declared and the identifiers used in a header or source text.
    void scan(const std::string& text);
    //! The standard templates the labs use (vector, array, numeric_limits, static_cast, ...).
    static Vocabulary standard();
};

//! One solution file, its mutation sites and their mutants.
class SourceFile {
public:
    //! Find the sites of `text` (solution blocks only); mutant ids start at `first_id`.
    //! \throw std::runtime_error on a lexing error or unbalanced markers.
    SourceFile(std::string file, std::string text, const Vocabulary& vocab, int first_id);

    const std::string& file() const { return file_; }
    const std::string& text() const { return text_; }
    const std::vector<Mutant>& mutants() const { return mutants_; }

    //! The file with mutant `m` applied (for a rebuild of that mutant alone).
    std::string apply(const Mutant& m) const;

    //! Where a schema put one mutant: output line and columns [col_first, col_last] (1-based).
    struct Span {
        int id = 0, line = 0, col_first = 0, col_last = 0;
    };
    //! The schema of this file: the mutants whose ids are in `ids` selectable at run time (others left out).
    //! `spans` (optional) receives where each mutant's text went, to map compiler errors back to mutants.
    //! `relax`: constexpr variables become const (initialised at start-up), so that the mutants of constexpr
    //! code (tables built at compile time) can be selected at run time too.
    std::string schema(const std::set<int>& ids, std::vector<Span>* spans = nullptr, bool relax = false) const;

    // One mutation site: how its mutants are written into the schema.
    //! One mutation site (internal): how its mutants are written into the schema.
    struct Site {
        enum class Form {
            binop,    // token replaced by "op rt::bin<K, code>() op": the same precedence and associativity
            prefix,   // a unary '!' or '-' replaced by "rt::un<K, code>() ->*"
            choice,   // tokens [first, last] copied once per mutant with token `tok` replaced: (on(K) ? ... : orig)
            logical,  // "&&" -> "&& rt::logic<K, code>() && [&]() -> bool { return bool(R); }"
            wrap,     // [first, last] between prefix and suffix (dropped statements, compound assignments)
        };
        Form form = Form::binop;
        std::size_t tok = 0, first = 0, last = 0;
        std::vector<int> ids;            // this site's mutants
        std::vector<std::string> alts;   // the replacement text of the token, per mutant (choice)
        int code = 0;                    // binop/prefix/logical: which operation
        std::string prefix, suffix;      // wrap / logical (the lambda around R)
    };

private:
    std::string file_, text_;
    std::vector<Token> tokens_;  // code tokens only (no comments or preprocessor lines)
    std::vector<Mutant> mutants_;
    std::vector<Site> sites_;
    //! the `constexpr` tokens a relaxed schema rewrites, and their text there: `const` (a variable), `inline` (a
    //! function) or nothing (a lambda)
    std::vector<std::pair<std::size_t, std::string>> relax_tokens_;
    //! the constexpr variables at namespace scope (tables): a relaxed schema digests their bytes at start-up
    struct Table {
        std::size_t end = 0;             // the token ';' that ends the declaration
        std::vector<std::string> names;  // the variables it declares
    };
    std::vector<Table> tables_;
    int first_id_ = 0;
};

//! The run-time half of the schema (namespace geolab_mutant_rt), put at the top of every schema file.
const std::string& schema_preamble();

// ---- running ------------------------------------------------------------------------------------------------

//! How a mutant ended.
enum class Outcome { killed, timed_out, survived, stillborn, equivalent };
const char* to_string(Outcome o);

//! The options of `geolab mutate`.
struct MutateOptions {
    std::filesystem::path source;  //!< the course tree (with solutions/)
    std::filesystem::path build;   //!< its Ninja build (compile_commands.json, test_<lab>_solution)
    std::string lab;               //!< e.g. "01_halfedge"
    std::size_t max = 0;           //!< 0: every mutant; else a random sample of this many
    unsigned long long seed = 1;   //!< of the sample
    int jobs = 1;                  //!< mutants run at once
    std::string only;              //!< only these: FILE (basename or path under solutions/NN_name) or FILE:LINE,
                                   //!< several separated by commas
    std::filesystem::path log;     //!< JSON lines, one per mutant (empty: none)
    bool resume = false;           //!< skip the mutants already in the log
    bool rerun_survivors = false;  //!< with resume: grade the log's survivors again (after tests were added)
    bool full = false;             //!< run every test of a mutant (default: stop at the first failure)
    bool array_bounds = false;     //!< also the mutants of array bounds (Mutant::array_bound; rebuilt alone)
    std::string order = "killer";  //!< test order: killer (last killer of the file, then cheap), cheap, listing
    double timeout_factor = 10;    //!< a test is timed out after factor × its baseline time + 2 s (≤ its limit)
    bool quiet = false;
    std::function<void(const std::string&)> progress;  //!< progress lines (stderr)
};

//! One mutant's result.
struct MutantResult {
    Mutant mutant;
    Outcome outcome = Outcome::survived;
    std::string mode;      //!< "schema", "rebuild", "tables" (proven equivalent), or "log" (taken from --log on --resume)
    bool proven = false;   //!< equivalent, proven by the tool: the same constexpr tables (see run_mutate)
    std::string detail;    //!< the killing test and its status, or the compiler's first error
    std::string anchor;    //!< see anchor(): what equivalent-mutants.txt matches
    int tests_run = 0;
    double seconds = 0;
};

//! Everything one run found.
struct MutateReport {
    std::string lab;
    std::size_t sites = 0, total_mutants = 0;  //!< in the solution blocks (before sampling)
    std::size_t array_bound_mutants = 0;       //!< array bounds left out (without --array-bounds), beside total_mutants
    std::vector<MutantResult> results;         //!< sampled mutants, by id
    std::vector<std::string> stale_equivalents;   //!< listed in equivalent-mutants.txt, matching no mutant
    std::vector<std::string> killed_equivalents;  //!< listed as equivalent, yet killed by the tests
    std::size_t schema_mutants = 0, rebuilt_mutants = 0;
    std::size_t baseline_tests = 0;
    double baseline_score = 0, baseline_max = 0;
    double build_seconds = 0, baseline_seconds = 0, seconds = 0;
    std::size_t tests_run = 0;
    std::size_t count(Outcome o) const;
    std::size_t proven_equivalents() const;  //!< equivalent mutants the tool proved so (the rest were reviewed)
    //! killed (timed out included) / (killed + survived); equivalent and stillborn mutants excluded.
    double rate() const;
};

//! Run `geolab mutate`. \throw std::runtime_error for what stops the run before any mutant ran (dirty
//! solutions/, no build, a baseline that does not list its tests).
MutateReport run_mutate(const MutateOptions& opt);

//! The report as text (summary, survivors, equivalents) and as one JSON object.
std::string format_report(const MutateReport& rep);
std::string report_json(const MutateReport& rep);

//! The anchor of a mutant in `text` (its file): "HHHHHHHH+C", the FNV-1a hash (32 bits, hex) of the mutated
//! token's source line with surrounding white space removed, and the token's 1-based column in that trimmed
//! line. It does not change when lines are inserted or removed above the site, or the line is re-indented.
std::string anchor(const std::string& text, const Mutant& m);

//! One reviewed equivalent mutant (a line of equivalent-mutants.txt).
struct Equivalent {
    std::string file;                 //!< e.g. "src/qef.cpp"
    int line = 0, col = 0;            //!< where it was when reviewed (a hint when `anchor` is given)
    std::string original, mutated;
    std::string anchor;               //!< "HHHHHHHH+C" (see anchor()); empty in the old three-field format
    std::string reason;
    int entry_line = 0;               //!< its line in equivalent-mutants.txt
    //! "file:line:col | original -> mutated", as the report names mutants.
    std::string key() const;
};

//! The entries of an equivalent-mutants.txt, one per line, '#' comments:
//! "file:line:col | original -> mutated | anchor | reason" (anchor: see anchor()), or the old
//! "file:line:col | original -> mutated | reason" (matched by line and column only).
//! \throw std::runtime_error "PATH:LINE: ..." on a malformed line.
std::vector<Equivalent> read_equivalents(const std::filesystem::path& file);

//! Which mutant each entry names (index into `mutants`, or -1: none, a stale entry). With an anchor: the
//! mutant of the same file and change whose anchor is the entry's, the nearest to the entry's line (the line
//! number is only a hint: the code may have moved). Without: the mutant whose key() is the entry's.
//! `texts` maps a file ("src/qef.cpp") to its current text.
std::vector<int> match_equivalents(const std::vector<Equivalent>& entries, const std::vector<Mutant>& mutants,
                                   const std::map<std::string, std::string>& texts);

}  // namespace geolab::grading::mutate
