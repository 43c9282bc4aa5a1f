// Tests of geolab mutate's lexer and mutation sites: comments, literals (raw strings too), preprocessor lines
// and template angle brackets are never mutated; every operator family finds its sites; the schema keeps the
// code's text outside the sites.
#include <algorithm>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "geolab/grading/mutate.hpp"

namespace mut = geolab::grading::mutate;

namespace {

// The file wrapped in one solution block.
std::string block(const std::string& code) { return "// BEGIN SOLUTION\n" + code + "\n// END SOLUTION\n"; }

std::vector<mut::Mutant> mutants_of(const std::string& text, mut::Vocabulary vocab = mut::Vocabulary::standard()) {
    vocab.scan(text);
    return mut::SourceFile("src/x.cpp", text, vocab, 0).mutants();
}

// "original -> mutated" of every mutant, in order.
std::vector<std::string> changes(const std::vector<mut::Mutant>& ms) {
    std::vector<std::string> out;
    for (const auto& m : ms) out.push_back(m.original + " -> " + m.mutated);
    return out;
}

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

}  // namespace

TEST_CASE("lexer: comments, strings, raw strings, characters and directives are single tokens") {
    const std::string src = "#include <vector> // x < y\n"
                            "auto s = R\"d(a < b // not a comment )\" still)d\"; char c = '<'; /* a<b */ int n = 1'000;\n"
                            "const char* t = \"q\\\"<\"; x >>= 2;";
    const auto toks = mut::lex(src, "t.cpp");
    std::vector<std::string> texts;
    for (const auto& t : toks) texts.push_back(t.text);
    CHECK(toks[0].kind == mut::TokenKind::preprocessor);
    CHECK(toks[0].text == "#include <vector> // x < y");
    CHECK(has(texts, "R\"d(a < b // not a comment )\" still)d\""));
    CHECK(has(texts, "'<'"));
    CHECK(has(texts, "/* a<b */"));
    CHECK(has(texts, "1'000"));
    CHECK(has(texts, "\"q\\\"<\""));
    CHECK(has(texts, ">>="));
    const auto raw = std::find(texts.begin(), texts.end(), "R\"d(a < b // not a comment )\" still)d\"");
    CHECK(toks[static_cast<std::size_t>(raw - texts.begin())].line == 2);
    CHECK_THROWS_WITH(mut::lex("int a; /* open", "bad.cpp"), doctest::Contains("bad.cpp:1: unterminated /* comment"));
    CHECK_THROWS_WITH(mut::lex("auto s = R\"x(never closed", "bad.cpp"), doctest::Contains("unterminated raw string"));
}

TEST_CASE("sites: only inside solution blocks, never in comments, strings or characters") {
    const std::string text = "int f(int a, int b) { return a < b; }\n" +
                             block("bool g(int a, int b) {\n"
                                   "  // if (a < b) return a + b;\n"
                                   "  const char* s = R\"(a < b // a + b)\";\n"
                                   "  if (s[0] == '<') return true;\n"
                                   "  return a <= b;\n"
                                   "}");
    const auto ms = mutants_of(text);
    const auto c = changes(ms);
    CHECK(has(c, "== -> !="));
    CHECK(has(c, "<= -> <"));
    CHECK(has(c, "<= -> >"));
    CHECK(has(c, "0 -> 1"));
    CHECK(has(c, "return true; -> (dropped)"));
    for (const auto& m : ms) {
        CHECK(m.line >= 5);  // nothing on line 1 (outside) or 3 (comment)
        CHECK(m.line != 3);
        CHECK(m.original != "<");  // the '<' of the raw string and of the character
        CHECK(m.original != "+");
    }
}

TEST_CASE("sites: template angle brackets are not comparisons") {
    const std::string text = block("template <class T> struct Box { T v; };\n"
                                   "int h(int x, int n) {\n"
                                   "  std::vector<int> v;\n"
                                   "  std::vector<std::vector<int>> vv;\n"
                                   "  std::array<double, 3> a{};\n"
                                   "  Box<int> b{};\n"
                                   "  if (static_cast<int>(x) < n) return std::numeric_limits<int>::max();\n"
                                   "  return x >> 2;\n"
                                   "}");
    const auto ms = mutants_of(text);
    int lt = 0;
    for (const auto& m : ms) {
        if (m.original == "<") {
            ++lt;
            CHECK(m.line == 8);
            CHECK(m.col == 27);
        }
        CHECK(m.original != ">");
        CHECK(m.original != "3");  // a template argument
    }
    CHECK(lt == 2);  // < -> <=, < -> >=
    CHECK(has(changes(ms), "2 -> 3"));
}

TEST_CASE("sites: every operator family") {
    const std::string text = block("double k(const Mesh& mesh, Halfedge h, double a, double b, bool p, bool q) {\n"
                                   "  double s = -a * 2.5 + b / a - 1;\n"
                                   "  s += a;\n"
                                   "  if (!p && q) s = std::min(s, a);\n"
                                   "  for (int i = 0; i < 3; ++i) {\n"
                                   "    if (p || i == 2) break;\n"
                                   "    if (q) continue;\n"
                                   "  }\n"
                                   "  Halfedge g = mesh.next(h);\n"
                                   "  auto pr = std::make_pair(1, 2);\n"
                                   "  return s + pr.first + mesh.to_vertex(g);\n"
                                   "}");
    mut::Vocabulary vocab = mut::Vocabulary::standard();
    vocab.identifiers.insert("prev");
    vocab.identifiers.insert("from_vertex");
    vocab.identifiers.insert("second");
    const auto ms = mutants_of(text, vocab);
    const auto c = changes(ms);
    for (const char* want : {"- -> (dropped)", "* -> /", "2.5 -> 5.0", "2.5 -> (-2.5)", "+ -> -", "/ -> *", "- -> +",
                             "1 -> 2", "1 -> 0", "+= -> -=", "! -> (dropped)", "&& -> ||", "min -> max", "0 -> 1",
                             "< -> <=", "< -> >=", "|| -> &&", "== -> !=", "break; -> (dropped)",
                             "continue; -> (dropped)", "next -> prev", "first -> second", "to_vertex -> from_vertex"})
        CHECK_MESSAGE(has(c, want), std::string(want));
    // the final return of a function is not dropped (it would fall off the end), nor is '++i' mutated
    CHECK_FALSE(has(c, "return s + pr.first + mesh.to_vertex(g); -> (dropped)"));
    // declarations are not multiplications
    for (const auto& m : ms) CHECK(!(m.original == "*" && m.line == 2 && m.col < 10));
}

TEST_CASE("mutants: apply edits exactly one range; keys name file, line, column and change") {
    const std::string text = block("int f(int a) {\n  if (a > 0) return 1;\n  return a;\n}");
    mut::Vocabulary vocab = mut::Vocabulary::standard();
    const mut::SourceFile file("src/x.cpp", text, vocab, 10);
    const auto& ms = file.mutants();
    REQUIRE(!ms.empty());
    CHECK(ms.front().id == 10);
    const auto gt = std::find_if(ms.begin(), ms.end(), [](const mut::Mutant& m) { return m.mutated == ">="; });
    REQUIRE(gt != ms.end());
    CHECK(gt->key() == "src/x.cpp:3:9 | > -> >=");
    CHECK(file.apply(*gt).find("if (a >= 0) return 1;") != std::string::npos);
    const auto drop = std::find_if(ms.begin(), ms.end(), [](const mut::Mutant& m) { return m.kind == "drop-return"; });
    REQUIRE(drop != ms.end());
    CHECK(file.apply(*drop).find("if (a > 0) ;\n") != std::string::npos);
}

TEST_CASE("schema: the code outside the sites is unchanged; every chosen mutant is selectable") {
    const std::string text = block("int f(int a) {\n  if (a > 0 && a != 7) return a - 1;\n  return -a;\n}");
    mut::Vocabulary vocab = mut::Vocabulary::standard();
    const mut::SourceFile file("src/x.cpp", text, vocab, 0);
    std::set<int> all;
    for (const auto& m : file.mutants()) all.insert(m.id);
    std::vector<mut::SourceFile::Span> spans;
    const std::string schema = file.schema(all, &spans);
    CHECK(schema.rfind(mut::schema_preamble(), 0) == 0);
    const std::string body = schema.substr(mut::schema_preamble().size());
    CHECK(body.find("int f(int a) {") != std::string::npos);
    CHECK(body.find("geolab_mutant_rt::Logic<") != std::string::npos);
    CHECK(body.find("[&]() -> bool { return static_cast<bool>(a != ") != std::string::npos);
    CHECK(body.find("{ if (!geolab_mutant_rt::on(") != std::string::npos);
    std::set<int> spanned;
    for (const auto& s : spans) spanned.insert(s.id);
    CHECK(spanned == all);
    // nothing chosen: the file itself after the preamble, then the line that marks the end of its start-up
    const std::string none = file.schema({});
    CHECK(none.rfind(mut::schema_preamble() + text, 0) == 0);
    CHECK(none.substr(mut::schema_preamble().size() + text.size()) ==
          "\nstatic const bool geolab_mutant_started = geolab_mutant_rt::started(0, " +
              std::to_string(file.mutants().size() - 1) + ");\n");
}

TEST_CASE("sites: an array bound in a declaration is a constant; a subscript after a product is not") {
    const std::string text = block("double f(const double* a, double x) {\n"
                                   "  const double* rows[2] = {a, a};\n"
                                   "  double b[3] = {1, 2, 3};\n"
                                   "  return a[0] * a[4] + x * b[1] + 2 * rows[1][0];\n"
                                   "}");
    const auto ms = mutants_of(text);
    for (const auto& m : ms) {
        const bool bound = (m.line == 3 && m.original == "2") || (m.line == 4 && m.original == "3" && m.col < 15);
        if (bound) CHECK_MESSAGE(!m.schema_ok, m.key() << " is an array bound: rebuilt alone");
        CHECK_MESSAGE(m.array_bound == bound, m.key() << (bound ? " is" : " is not") << " an array bound");
        if (m.line == 4 && !bound) CHECK_MESSAGE(m.schema_ok, m.key() << " is an initializer's value: in the schema");
        if (m.line == 5) CHECK_MESSAGE(m.schema_ok, m.key() << " is an ordinary subscript: in the schema");
    }
    const auto c = changes(ms);
    CHECK(has(c, "4 -> 5"));  // a[4]
    CHECK(has(c, "1 -> 2"));
}

TEST_CASE("sites: a later declarator's array bound is a constant too; a call's argument subscript is not") {
    const std::string text = block("int f(const int* a, int i) {\n"
                                   "  int dx[4], dy[5];\n"
                                   "  const int qb[2] = {1, 2}, qc[3] = {4, 5, 6};\n"
                                   "  return g(a[1], a[6]) + dx[i] + dy[i] + qb[1] + qc[2];\n"
                                   "}");
    int bounds = 0, later = 0;
    for (const auto& m : mutants_of(text)) {
        // line 3: the bounds 4 and 5; line 4: qb's 2 (column 16) and qc's 3 (column 32), the rest initializers
        const bool bound = m.line == 3 || (m.line == 4 && (m.col == 16 || m.col == 32));
        if (bound) {
            CHECK_MESSAGE(!m.schema_ok, m.key() << " is an array bound (first or later declarator): rebuilt alone");
            ++bounds;
            later += (m.line == 3 && m.original == "5") || (m.line == 4 && m.col == 32);
        } else {
            CHECK_MESSAGE(m.schema_ok, m.key() << " is an initializer, a subscript or an argument: in the schema");
        }
    }
    CHECK(bounds >= 4);
    CHECK(later >= 2);  // dy's 5 and qc's 3: the declarators after a comma
}

TEST_CASE("schema: a relaxed schema drops static_assert (its constexpr functions are inline there)") {
    const std::string text = "namespace geolab::dc {\nnamespace {\n" +
                             block("constexpr int sq(int x) { return x * x; }\n"
                                   "static_assert(sq(3) == 9, \"squares\");\n"
                                   "int f(int i) { return sq(i) + 1; }") +
                             "}\n}\n";
    const mut::SourceFile file("src/x.cpp", text, mut::Vocabulary::standard(), 0);
    std::set<int> all;
    for (const auto& m : file.mutants()) all.insert(m.id);
    const std::string relaxed = file.schema(all, nullptr, true).substr(mut::schema_preamble().size());
    CHECK(relaxed.find("inline int sq(") != std::string::npos);
    CHECK(relaxed.find("GEOLAB_MUTANT_RELAXED_STATIC_ASSERT(") != std::string::npos);
    CHECK(relaxed.find("static_assert(sq") == std::string::npos);
    const std::string strict = file.schema({}, nullptr, false);
    CHECK(strict.find("static_assert(sq(3) == 9") != std::string::npos);
}

TEST_CASE("schema: a relaxed schema computes constexpr tables at start-up and digests them") {
    const std::string text = "namespace geolab::dc {\nnamespace {\n" +
                             block("struct T { int v[4] = {}; };\n"
                                   "constexpr T make() {\n  T t;\n  for (int i = 1; i < 4; ++i) t.v[i] = i * i;\n  return t;\n}\n"
                                   "constexpr T table = make(), other = make();\n"
                                   "constexpr int qb[2] = {-1, +1}, qc[2] = {1, 2};\n"
                                   "int f(int i) {\n  constexpr int local = 3;\n  return table.v[i & local] + qb[i & 1];\n}") +
                             "}\n}\n";
    const mut::SourceFile file("src/x.cpp", text, mut::Vocabulary::standard(), 0);
    std::set<int> relaxed, all;
    for (const auto& m : file.mutants()) {
        all.insert(m.id);
        if (m.needs_relax) relaxed.insert(m.id);
    }
    CHECK(relaxed.size() >= 4);  // the loop's 1, <, 4, * at least
    const std::string body = file.schema(all, nullptr, true).substr(mut::schema_preamble().size());
    CHECK(body.find("inline T make()") != std::string::npos);      // a constexpr function: inline
    CHECK(body.find("const T table = make()") != std::string::npos);  // a constexpr variable: const
    CHECK(body.find("constexpr") == std::string::npos);
    // each namespace-scope table (both declarators of a declaration) is digested after it; the local one is not
    for (const char* name : {"table", "other", "qb", "qc"})
        CHECK(body.find(std::string("geolab_mutant_rt::table(&") + name + ", sizeof(" + name + "))") != std::string::npos);
    CHECK(body.find("table(&local") == std::string::npos);
    // not relaxed: constexpr stays, nothing is digested
    const std::string strict = file.schema({}, nullptr, false);
    CHECK(strict.find("constexpr T make()") != std::string::npos);
    CHECK(strict.find("geolab_mutant_rt::table(&") == std::string::npos);
}

TEST_CASE("sites: a '*' after an if/while condition dereferences; 'std::uint16_t* e' declares a parameter") {
    const std::string text = block("void f(int* out, int x) {\n"
                                   "  if (out) *out = x * 2;\n"
                                   "  while (x > 0) *out += x--;\n"
                                   "  auto g = [&](const double* a, const std::uint16_t* e, int n) { return a[0] * e[n]; };\n"
                                   "  if (x) g(nullptr, nullptr, (x) * 3);\n"
                                   "}");
    int products = 0;
    for (const auto& m : mutants_of(text)) {
        if (m.original != "*") continue;
        ++products;
        const bool real = (m.line == 3 && m.col == 21) || (m.line == 5 && m.col == 78) || (m.line == 6 && m.col == 34);
        CHECK_MESSAGE(real, m.key() << ": a dereference or a pointer declarator read as a product");
    }
    CHECK(products == 3);  // x * 2, a[0] * e[n], (x) * 3 (each mutated to /)
}
