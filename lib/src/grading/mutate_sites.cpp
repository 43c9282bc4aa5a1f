// The lexer, the mutation sites and the mutant schema of `geolab mutate` (see grading/mutate.hpp).
#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <map>
#include <stdexcept>

#include "geolab/grading/mutate.hpp"

namespace geolab::grading::mutate {
namespace {

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return c >= '0' && c <= '9'; }

// Punctuators, longest first within each first character.
const char* const punctuators[] = {"<=>", "<<=", ">>=", "->*", "...", "::", "->", "++", "--", "<<", ">>", "<=",
                                   ">=",  "==",  "!=",  "&&",  "||",  "+=", "-=", "*=", "/=", "%=", "&=", "|=",
                                   "^=",  ".*",  "##"};

bool is_string_prefix(const std::string& id) {
    return id == "R" || id == "u8" || id == "u" || id == "U" || id == "L" || id == "u8R" || id == "uR" ||
           id == "UR" || id == "LR";
}

}  // namespace

std::vector<Token> lex(const std::string& s, const std::string& name) {
    std::vector<Token> out;
    std::size_t i = 0;
    int line = 1;
    std::size_t line_start = 0;
    bool line_has_code = false;  // a '#' is a directive only as the first token of a line
    auto fail = [&](const std::string& what, int at_line) {
        throw std::runtime_error(name + ":" + std::to_string(at_line) + ": unterminated " + what);
    };
    auto advance_to = [&](std::size_t end) {  // move i to end, counting lines
        for (; i < end; ++i)
            if (s[i] == '\n') {
                ++line;
                line_start = i + 1;
            }
    };
    auto push = [&](TokenKind kind, std::size_t begin, int at_line, std::size_t at_line_start) {
        Token t;
        t.kind = kind;
        t.offset = begin;
        t.length = i - begin;
        t.line = at_line;
        t.col = static_cast<int>(begin - at_line_start) + 1;
        t.text = s.substr(begin, i - begin);
        out.push_back(std::move(t));
    };
    while (i < s.size()) {
        const char c = s[i];
        if (c == '\n') {
            advance_to(i + 1);
            line_has_code = false;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++i;
            continue;
        }
        if (c == '\\' && i + 1 < s.size() && s[i + 1] == '\n') {  // a line splice outside a directive
            advance_to(i + 2);
            continue;
        }
        const std::size_t begin = i;
        const int at_line = line;
        const std::size_t at_line_start = line_start;
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            // To the end of the line; a backslash-newline continues a // comment.
            while (i < s.size() && s[i] != '\n') {
                if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == '\n') advance_to(i + 2);
                else ++i;
            }
            push(TokenKind::comment, begin, at_line, at_line_start);
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            const std::size_t end = s.find("*/", i + 2);
            if (end == std::string::npos) fail("/* comment", at_line);
            advance_to(end + 2);
            push(TokenKind::comment, begin, at_line, at_line_start);
            continue;
        }
        if (c == '#' && !line_has_code) {
            // A directive: to the end of the line, with splices; comments inside are part of it.
            while (i < s.size() && s[i] != '\n') {
                if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == '\n') advance_to(i + 2);
                else if (s[i] == '/' && i + 1 < s.size() && s[i + 1] == '*') {
                    const std::size_t end = s.find("*/", i + 2);
                    if (end == std::string::npos) fail("/* comment", line);
                    advance_to(end + 2);
                } else ++i;
            }
            push(TokenKind::preprocessor, begin, at_line, at_line_start);
            continue;
        }
        line_has_code = true;
        auto quoted = [&](char q) {  // i at the opening quote
            ++i;
            while (i < s.size() && s[i] != q) {
                if (s[i] == '\n') fail(q == '"' ? "string literal" : "character literal", at_line);
                if (s[i] == '\\' && i + 1 < s.size()) {
                    if (s[i + 1] == '\n') {
                        advance_to(i + 2);
                        continue;
                    }
                    i += 2;
                    continue;
                }
                ++i;
            }
            if (i >= s.size()) fail(q == '"' ? "string literal" : "character literal", at_line);
            ++i;
        };
        if (ident_start(c)) {
            while (i < s.size() && ident_char(s[i])) ++i;
            const std::string id = s.substr(begin, i - begin);
            if (i < s.size() && (s[i] == '"' || s[i] == '\'') && is_string_prefix(id)) {
                if (id.back() == 'R' && s[i] == '"') {
                    // R"delim( ... )delim"
                    const std::size_t open = s.find('(', i + 1);
                    if (open == std::string::npos || open - i - 1 > 16) fail("raw string literal", at_line);
                    const std::string close = ")" + s.substr(i + 1, open - i - 1) + "\"";
                    const std::size_t end = s.find(close, open + 1);
                    if (end == std::string::npos) fail("raw string literal", at_line);
                    advance_to(end + close.size());
                } else {
                    quoted(s[i]);
                }
                while (i < s.size() && ident_char(s[i])) ++i;  // user-defined literal suffix
                push(TokenKind::string, begin, at_line, at_line_start);
                continue;
            }
            push(TokenKind::identifier, begin, at_line, at_line_start);
            continue;
        }
        if (digit(c) || (c == '.' && i + 1 < s.size() && digit(s[i + 1]))) {
            // A pp-number: digits, letters, '.', digit separators, and signs after e/E/p/P.
            ++i;
            while (i < s.size()) {
                const char d = s[i];
                if ((d == '+' || d == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E' || s[i - 1] == 'p' || s[i - 1] == 'P') &&
                    !(s[begin] == '0' && begin + 1 < s.size() && (s[begin + 1] == 'x' || s[begin + 1] == 'X') &&
                      (s[i - 1] == 'e' || s[i - 1] == 'E'))) {
                    ++i;
                } else if (ident_char(d) || d == '.') {
                    ++i;
                } else if (d == '\'' && i + 1 < s.size() && ident_char(s[i + 1])) {
                    i += 2;
                } else {
                    break;
                }
            }
            push(TokenKind::number, begin, at_line, at_line_start);
            continue;
        }
        if (c == '"' || c == '\'') {
            quoted(c);
            while (i < s.size() && ident_char(s[i])) ++i;
            push(TokenKind::string, begin, at_line, at_line_start);
            continue;
        }
        std::size_t len = 1;
        for (const char* p : punctuators) {
            const std::size_t n = std::strlen(p);
            if (s.compare(i, n, p) == 0) {
                len = n;
                break;
            }
        }
        i += len;
        push(TokenKind::punct, begin, at_line, at_line_start);
    }
    return out;
}

std::string Mutant::key() const {
    return file + ":" + std::to_string(line) + ":" + std::to_string(col) + " | " + original + " -> " + mutated;
}

// ---- the vocabulary ----------------------------------------------------------------------------------------

Vocabulary Vocabulary::standard() {
    Vocabulary v;
    for (const char* n :
         {"vector", "array", "pair", "tuple", "optional", "variant", "span", "function", "map", "set", "multimap",
          "multiset", "unordered_map", "unordered_set", "deque", "list", "queue", "priority_queue", "stack",
          "basic_string", "basic_string_view", "unique_ptr", "shared_ptr", "weak_ptr", "make_unique", "make_shared",
          "numeric_limits", "initializer_list", "is_same", "is_same_v", "enable_if", "enable_if_t", "conditional",
          "conditional_t", "decay_t", "remove_cvref_t", "remove_reference_t", "underlying_type_t", "common_type_t",
          "invoke_result_t", "hash", "less", "greater", "equal_to", "plus", "minus", "get", "tuple_element",
          "tuple_size", "integral_constant", "bitset", "atomic", "duration", "duration_cast", "time_point", "ratio",
          "bit_cast", "vec", "mat", "qua", "any_cast", "min", "max", "clamp", "declval", "forward", "move", "exchange",
          "as_const", "pi_v", "e_v", "sqrt2_v", "static_pointer_cast", "mdspan", "extents", "iota_view",
          "back_insert_iterator", "istream_iterator", "ostream_iterator", "lock_guard", "unique_lock", "scoped_lock",
          "sort", "accumulate", "transform", "template", "uniform_int_distribution", "uniform_real_distribution",
          "normal_distribution", "mersenne_twister_engine", "ptr_fun", "to_underlying", "visit", "holds_alternative",
          "get_if", "in_place_type", "type_identity_t", "make_signed_t", "make_unsigned_t"})
        v.templates.insert(n);
    return v;
}

void Vocabulary::scan(const std::string& text) {
    std::vector<Token> toks;
    try {
        toks = lex(text, "(vocabulary)");
    } catch (const std::exception&) {
        return;  // a header that does not lex only costs us its names
    }
    std::vector<const Token*> code;
    for (const auto& t : toks)
        if (t.kind != TokenKind::comment && t.kind != TokenKind::preprocessor) code.push_back(&t);
    for (std::size_t i = 0; i < code.size(); ++i) {
        if (code[i]->kind == TokenKind::identifier) identifiers.insert(code[i]->text);
        if (code[i]->text != "template" || i + 1 >= code.size() || code[i + 1]->text != "<") continue;
        // Skip the template header, then take the declared name: the identifier after class/struct/using/
        // concept, or the last identifier before the first '(' (a function template).
        int depth = 0;
        std::size_t j = i + 1;
        for (; j < code.size(); ++j) {
            const std::string& t = code[j]->text;
            if (t == "<") ++depth;
            else if (t == ">") --depth;
            else if (t == ">>") depth -= 2;
            if (depth <= 0) break;
        }
        std::string last;
        for (++j; j < code.size(); ++j) {
            const std::string& t = code[j]->text;
            if (t == "class" || t == "struct" || t == "union" || t == "using" || t == "concept") {
                if (j + 1 < code.size() && code[j + 1]->kind == TokenKind::identifier) templates.insert(code[j + 1]->text);
                break;
            }
            if (t == "(") {
                if (!last.empty()) templates.insert(last);
                break;
            }
            if (t == ";" || t == "{" || t == "=") break;
            if (code[j]->kind == TokenKind::identifier && t != "operator") last = t;
        }
    }
}

// ---- sites ------------------------------------------------------------------------------------------------

namespace {

using Form = SourceFile::Site::Form;

const std::set<std::string>& keywords() {
    static const std::set<std::string> k = {
        "alignas", "alignof", "asm", "auto", "bool", "break", "case", "catch", "char", "char8_t", "char16_t",
        "char32_t", "class", "co_await", "co_return", "co_yield", "concept", "const", "consteval", "constexpr",
        "constinit", "const_cast", "continue", "decltype", "default", "delete", "do", "double", "dynamic_cast",
        "else", "enum", "explicit", "export", "extern", "float", "for", "friend", "goto", "if", "inline", "int",
        "long", "mutable", "namespace", "new", "noexcept", "operator", "private", "protected", "public", "register",
        "reinterpret_cast", "requires", "return", "short", "signed", "sizeof", "static", "static_assert",
        "static_cast", "struct", "switch", "template", "thread_local", "throw", "try", "typedef", "typeid",
        "typename", "union", "unsigned", "using", "virtual", "void", "volatile", "while"};
    return k;
}
const std::set<std::string>& type_words() {
    static const std::set<std::string> k = {"auto",   "bool",  "char", "double", "float", "int",  "long",
                                            "short",  "signed", "unsigned", "void", "const", "size_t",
                                            "ptrdiff_t", "uint32_t", "uint64_t", "int64_t", "int32_t", "uint8_t",
                                            "uint16_t", "int16_t", "int8_t", "uintptr_t", "intptr_t", "wchar_t",
                                            "char8_t", "char16_t", "char32_t"};
    return k;
}

// The swaps of identifiers: the other name (and the tokens that must surround it).
const std::map<std::string, std::string>& swaps() {
    static const std::map<std::string, std::string> m = {
        {"min", "max"},   {"max", "min"},           {"next", "prev"},           {"prev", "next"},
        {"first", "second"}, {"second", "first"}, {"from_vertex", "to_vertex"}, {"to_vertex", "from_vertex"},
        {"floor", "ceil"}, {"ceil", "floor"}};
    return m;
}

// Binary operations of the schema runtime, by code.
const char* const binop_names[] = {"<", "<=", ">", ">=", "==", "!=", "+", "-", "*", "/"};
int binop_code(const std::string& op) {
    for (int k = 0; k < 10; ++k)
        if (op == binop_names[k]) return k;
    return -1;
}

// The mutants of a binary operator: the other operators it becomes.
std::vector<std::string> binop_alternatives(const std::string& op) {
    if (op == "<") return {"<=", ">="};
    if (op == "<=") return {"<", ">"};
    if (op == ">") return {">=", "<="};
    if (op == ">=") return {">", "<"};
    if (op == "==") return {"!="};
    if (op == "!=") return {"=="};
    if (op == "+") return {"-"};
    if (op == "-") return {"+"};
    if (op == "*") return {"/"};
    if (op == "/") return {"*"};
    return {};
}

std::string kind_of(const std::string& op) {
    if (op == "<" || op == "<=" || op == ">" || op == ">=") return "relational";
    if (op == "==" || op == "!=") return "equality";
    return "arithmetic";
}

// The shortest decimal text of a double that reads back exactly, always with a '.' or an exponent.
std::string double_text(double v) {
    char buf[64];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    std::string t(buf, r.ptr);
    if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
    return t;
}

// The mutants of a numeric literal (empty when it is not a plain decimal literal).
std::vector<std::string> literal_alternatives(const std::string& lit) {
    std::string body = lit, suffix;
    if (lit.size() > 1 && lit[0] == '0' && (lit[1] == 'x' || lit[1] == 'X' || lit[1] == 'b' || lit[1] == 'B'))
        return {};
    if (lit.find('\'') != std::string::npos) return {};
    const bool floating = lit.find_first_of(".eE") != std::string::npos;
    std::size_t end = body.size();
    while (end > 0 && std::isalpha(static_cast<unsigned char>(body[end - 1])) &&
           !(floating && (body[end - 1] == 'e' || body[end - 1] == 'E')))
        --end;
    suffix = body.substr(end);
    body = body.substr(0, end);
    if (body.empty()) return {};
    if (!floating) {
        if (body.size() > 1 && body[0] == '0') return {};  // octal
        unsigned long long v = 0;
        auto r = std::from_chars(body.data(), body.data() + body.size(), v);
        if (r.ec != std::errc() || r.ptr != body.data() + body.size()) return {};
        std::vector<std::string> out{std::to_string(v + 1) + suffix};
        if (v > 0) out.push_back(std::to_string(v - 1) + suffix);
        return out;
    }
    const double v = std::strtod(body.c_str(), nullptr);
    if (v == 0.0) return {"1.0" + suffix};
    return {double_text(v * 2) + suffix, "(" + double_text(-v) + suffix + ")"};
}

// What the analysis of the token stream knows about each code token.
struct TokenInfo {
    bool in_solution = false;
    bool in_template_args = false;  // between template angle brackets
    bool unevaluated = false;       // inside decltype/sizeof/noexcept/static_assert/alignas/requires/case/enum
    bool constant = false;          // inside a constexpr/consteval declaration or an if constexpr condition
    bool hard = false;              // constant whatever the schema does (array bound, if constexpr, consteval)
    bool array_bound = false;       // inside the brackets of an array bound of a declaration
    bool template_open = false, template_close = false;
    std::size_t match = std::string::npos;  // the matching bracket of ( [ { and template < >
};

}  // namespace

SourceFile::SourceFile(std::string file, std::string text, const Vocabulary& vocab, int first_id)
    : file_(std::move(file)), text_(std::move(text)), first_id_(first_id) {
    const std::vector<Token> all = lex(text_, file_);
    // The solution blocks: byte ranges between "// BEGIN SOLUTION" and "// END SOLUTION" comments.
    std::vector<std::pair<std::size_t, std::size_t>> blocks;
    std::size_t open_at = std::string::npos;
    int open_line = 0;
    for (const auto& t : all) {
        if (t.kind != TokenKind::comment) {
            if (t.kind != TokenKind::preprocessor) tokens_.push_back(t);
            continue;
        }
        if (t.text.rfind("// BEGIN SOLUTION", 0) == 0) {
            if (open_at != std::string::npos)
                throw std::runtime_error(file_ + ":" + std::to_string(t.line) + ": nested BEGIN SOLUTION (the block opened at line " +
                                         std::to_string(open_line) + " is not closed)");
            open_at = t.offset + t.length;
            open_line = t.line;
        } else if (t.text.rfind("// END SOLUTION", 0) == 0) {
            if (open_at == std::string::npos)
                throw std::runtime_error(file_ + ":" + std::to_string(t.line) + ": END SOLUTION without BEGIN SOLUTION");
            blocks.push_back({open_at, t.offset});
            open_at = std::string::npos;
        }
    }
    if (open_at != std::string::npos)
        throw std::runtime_error(file_ + ":" + std::to_string(open_line) + ": BEGIN SOLUTION is never closed");

    const std::size_t n = tokens_.size();
    std::vector<TokenInfo> info(n);
    auto txt = [&](std::size_t i) -> const std::string& {
        static const std::string none;
        return i < n ? tokens_[i].text : none;
    };
    auto kind = [&](std::size_t i) { return i < n ? tokens_[i].kind : TokenKind::comment; };
    for (std::size_t i = 0, b = 0; i < n; ++i) {
        while (b < blocks.size() && blocks[b].second <= tokens_[i].offset) ++b;
        info[i].in_solution = b < blocks.size() && tokens_[i].offset >= blocks[b].first;
    }

    // 1. Brackets, template angle brackets included. A '<' opens template arguments after a known template
    //    name, a *_cast, or "template"; a '<' left open at a ')' ']' '}' or ';' was a comparison after all.
    {
        std::vector<std::size_t> stack;
        auto is_template_name = [&](std::size_t i) {
            if (i == 0 || kind(i - 1) != TokenKind::identifier) return false;
            const std::string& p = txt(i - 1);
            if (p == "operator") return false;
            if (vocab.templates.count(p) || (p.size() > 5 && p.compare(p.size() - 5, 5, "_cast") == 0)) return true;
            if (p == "template") return true;
            return i >= 2 && txt(i - 2) == "template";
        };
        for (std::size_t i = 0; i < n; ++i) {
            const std::string& t = txt(i);
            if (kind(i) != TokenKind::punct) continue;
            if (t == "<" && is_template_name(i)) {
                info[i].template_open = true;
                stack.push_back(i);
            } else if ((t == ">" || t == ">>" || t == ">=" || t == ">>=") && !stack.empty() && txt(stack.back()) == "<") {
                const int closes = (t == ">>" || t == ">>=") ? 2 : 1;
                for (int c = 0; c < closes && !stack.empty() && txt(stack.back()) == "<"; ++c) {
                    info[stack.back()].match = i;
                    info[i].match = stack.back();
                    stack.pop_back();
                }
                info[i].template_close = true;
            } else if (t == "(" || t == "[" || t == "{") {
                stack.push_back(i);
            } else if (t == ")" || t == "]" || t == "}" || t == ";") {
                while (!stack.empty() && txt(stack.back()) == "<") {  // not a template after all
                    info[stack.back()].template_open = false;
                    stack.pop_back();
                }
                if (t != ";" && !stack.empty()) {
                    info[stack.back()].match = i;
                    info[i].match = stack.back();
                    stack.pop_back();
                }
            }
        }
        for (std::size_t i = 0; i < n; ++i)
            if (info[i].template_open && info[i].match != std::string::npos)
                for (std::size_t j = i + 1; j < info[i].match; ++j) info[j].in_template_args = true;
    }
    // Whether token i is at namespace scope: no enclosing brace, or only those of namespaces and extern "C".
    auto at_namespace_scope = [&](std::size_t i) {
        int depth = 0;
        for (std::size_t q = i; q-- > 0;) {
            if (txt(q) == "}") ++depth;
            else if (txt(q) == "{" && depth > 0) --depth;
            else if (txt(q) == "{") {
                std::size_t p = q;
                while (p > 0 && ((kind(p - 1) == TokenKind::identifier && txt(p - 1) != "namespace") || txt(p - 1) == "::"))
                    --p;                                                  // its name (a::b)
                if (p > 0 && kind(p - 1) == TokenKind::string) --p;  // extern "C"
                if (p == 0 || (txt(p - 1) != "namespace" && txt(p - 1) != "extern")) return false;
            }
        }
        return true;
    };
    // The comma-separated pieces of tokens [first, end) at bracket depth 0: (first, last exclusive) each.
    auto top_level_pieces = [&](std::size_t first, std::size_t end) {
        std::vector<std::pair<std::size_t, std::size_t>> out;
        std::size_t start = first;
        for (std::size_t k = first; k < end; ++k) {
            const std::string& u = txt(k);
            if ((u == "(" || u == "[" || u == "{" || (u == "<" && info[k].template_open)) && info[k].match != std::string::npos &&
                info[k].match < end) {
                k = info[k].match;
                continue;
            }
            if (u == ",") {
                out.push_back({start, k});
                start = k + 1;
            }
        }
        out.push_back({start, end});
        return out;
    };

    // 2. Unevaluated and constant contexts.
    for (std::size_t i = 0; i < n; ++i) {
        const std::string& t = txt(i);
        if ((t == "decltype" || t == "sizeof" || t == "alignof" || t == "noexcept" || t == "static_assert" ||
             t == "alignas" || t == "requires" || t == "typeid") &&
            txt(i + 1) == "(" && info[i + 1].match != std::string::npos) {
            for (std::size_t j = i + 1; j <= info[i + 1].match; ++j) info[j].unevaluated = true;
            // A relaxed schema's constexpr functions are inline, so a static_assert that calls one cannot be
            // evaluated: it goes (a compile-time self-check of the reference; a mutant that breaks it would not
            // compile, and in the schema it is graded by the tests instead).
            if (t == "static_assert") relax_tokens_.push_back({i, "GEOLAB_MUTANT_RELAXED_STATIC_ASSERT"});
        } else if (t == "case") {
            for (std::size_t j = i + 1; j < n && txt(j) != ":"; ++j) info[j].unevaluated = true;
        } else if (t == "enum") {
            std::size_t j = i + 1;
            while (j < n && txt(j) != "{" && txt(j) != ";") ++j;
            if (j < n && txt(j) == "{" && info[j].match != std::string::npos)
                for (std::size_t k = j; k <= info[j].match; ++k) info[k].unevaluated = true;
        } else if (t == "constexpr" || t == "consteval" || t == "constinit") {
            if (i > 0 && txt(i - 1) == "if") {
                if (txt(i + 1) == "(" && info[i + 1].match != std::string::npos)
                    for (std::size_t j = i + 1; j <= info[i + 1].match; ++j) info[j].constant = info[j].hard = true;
                continue;
            }
            // A declaration: to its ';' at depth 0, or to the end of its body when a '{' comes first after a ')'.
            std::size_t j = i + 1;
            bool function = false;
            for (; j < n; ++j) {
                const std::string& u = txt(j);
                if (u == ";") break;
                if ((u == "(" || u == "[" || (u == "<" && info[j].template_open)) && info[j].match != std::string::npos) {
                    j = info[j].match;
                    continue;
                }
                if (u == "{" && info[j].match != std::string::npos) {
                    const bool body = j > 0 && (txt(j - 1) == ")" || txt(j - 1) == "const" || txt(j - 1) == "noexcept");
                    j = info[j].match;
                    if (body) {
                        function = true;
                        break;
                    }
                }
            }
            // A relaxed schema computes constexpr tables at start-up, so that their mutants can be selected at
            // run time: a constexpr variable becomes const, a constexpr function inline (GCC rejects a call of the
            // schema's run-time choice in a constexpr function's body, and names one such call per function and
            // compile: kept constexpr, a function with n sites would cost n failed compiles) and a lambda's
            // constexpr goes. Not so for consteval, constinit and static data members (a static const double
            // member cannot have an initializer).
            const bool lambda = i > 0 && (txt(i - 1) == ")" || txt(i - 1) == "]");
            const bool relaxable = t == "constexpr" && (function || lambda || !(i > 0 && txt(i - 1) == "static"));
            if (relaxable) relax_tokens_.push_back({i, function ? "inline" : lambda ? "" : "const"});
            if (relaxable && !function && !lambda && j < n && at_namespace_scope(i)) {
                // A table computed at start-up in a relaxed schema: its bytes are digested there (tables_).
                Table tab;
                tab.end = j;
                for (const auto& [first, last] : top_level_pieces(i + 1, j)) {
                    // the declared name: the identifier before the piece's first top-level '=', '{' or '['
                    for (std::size_t k = first + 1; k < last; ++k) {
                        const std::string& u = txt(k);
                        if (u == "=" || u == "{" || u == "[") {
                            if (kind(k - 1) == TokenKind::identifier) tab.names.push_back(txt(k - 1));
                            break;
                        }
                        if ((u == "(" || (u == "<" && info[k].template_open)) && info[k].match != std::string::npos)
                            k = info[k].match;
                    }
                }
                if (!tab.names.empty()) tables_.push_back(std::move(tab));
            }
            for (std::size_t k = i; k <= std::min(j, n - 1); ++k) {
                info[k].constant = true;
                if (!relaxable) info[k].hard = true;
            }
        }
    }

    // Array bounds in declarations ("double a[3][3]") and default member initializers of classes are constant
    // expressions (or may be used in one): their sites are rebuilt alone.
    {
        std::vector<char> declarator(n, 0);
        // "T* name[" declares an array of pointers; "x * name[" multiplies: the '*' (or '&') must follow a type
        // that starts a declaration (after ; { } ( , or a specifier such as const), not an operand
        auto pointer_declarator = [&](std::size_t star) {
            if (star < 1) return false;
            std::size_t t = star - 1;
            if (type_words().count(txt(t)) || info[t].template_close) return true;
            if (kind(t) != TokenKind::identifier || keywords().count(txt(t))) return false;
            while (t >= 2 && txt(t - 1) == "::" && kind(t - 2) == TokenKind::identifier) t -= 2;  // a::b::T
            if (t == 0) return true;
            const std::string& before = txt(t - 1);
            return before == ";" || before == "{" || before == "}" || before == "(" || before == "," ||
                   before == "const" || before == "static" || before == "constexpr" || before == "inline" ||
                   before == "extern" || before == "volatile" || before == "mutable" || before == "thread_local";
        };
        // "int dx[4], dy[4]" and "constexpr int a[2] = {1, 2}, b[2] = ...": a later declarator of a declaration,
        // after a ',' at the statement's own depth, in a statement that starts (after specifiers) with a type
        auto later_declarator = [&](std::size_t comma) {
            static const std::set<std::string> specifiers{"const",  "static",   "constexpr",    "inline",   "extern",
                                                          "volatile", "mutable", "thread_local", "constinit"};
            std::size_t t = comma;
            while (t > 0) {
                const std::size_t k = t - 1;
                const std::string& u = txt(k);
                const bool closer = u == ")" || u == "]" || (u == "}" && txt(k + 1) == ",") ||
                                    (u == ">" && info[k].template_close);
                if (closer && info[k].match != std::string::npos) {
                    t = info[k].match;
                    continue;
                }
                if (u == ";" || u == "{" || u == "}") break;
                if (u == "(" || u == "[" || u == "<") return false;  // a call's arguments, a subscript, a comparison
                t = k;
            }
            while (t < comma && specifiers.count(txt(t))) ++t;
            if (t + 1 >= comma) return false;
            if (type_words().count(txt(t))) return true;
            return kind(t) == TokenKind::identifier && !keywords().count(txt(t)) &&
                   (kind(t + 1) == TokenKind::identifier || txt(t + 1) == "::" ||
                    (txt(t + 1) == "<" && info[t + 1].template_open));
        };
        for (std::size_t i = 2; i < n; ++i) {
            if (txt(i) != "[" || info[i].match == std::string::npos) continue;
            const bool after_name = kind(i - 1) == TokenKind::identifier && !keywords().count(txt(i - 1)) &&
                                    (type_words().count(txt(i - 2)) || info[i - 2].template_close ||
                                     ((txt(i - 2) == "*" || txt(i - 2) == "&") && pointer_declarator(i - 2)) ||
                                     (kind(i - 2) == TokenKind::identifier && !keywords().count(txt(i - 2))) ||
                                     (txt(i - 2) == "," && later_declarator(i - 2)));
            const bool next_dim = txt(i - 1) == "]" && info[i - 1].match != std::string::npos && declarator[info[i - 1].match];
            if (!after_name && !next_dim) continue;
            declarator[i] = 1;
            for (std::size_t j = i; j <= info[i].match; ++j) info[j].constant = info[j].hard = info[j].array_bound = true;
        }
        for (std::size_t i = 0; i + 1 < n; ++i) {
            if (txt(i) != "struct" && txt(i) != "class" && txt(i) != "union") continue;
            std::size_t j = i + 1;
            while (j < n && txt(j) != "{" && txt(j) != ";" && txt(j) != "(" && txt(j) != ")") ++j;
            if (j >= n || txt(j) != "{" || info[j].match == std::string::npos) continue;
            // members at the class body's own depth: from '=' or '{' of a member to its ';'
            for (std::size_t k = j + 1; k < info[j].match; ++k) {
                if (txt(k) == "{" && info[k].match != std::string::npos && k > 0 && (txt(k - 1) == ")" || txt(k - 1) == "const")) {
                    k = info[k].match;  // a member function's body: ordinary code
                    continue;
                }
                if ((txt(k) == "(" || txt(k) == "[") && info[k].match != std::string::npos) {
                    k = info[k].match;
                    continue;
                }
                if (txt(k) == "=" || (txt(k) == "{" && kind(k - 1) == TokenKind::identifier)) {
                    std::size_t e = k;
                    while (e < info[j].match && txt(e) != ";") {
                        if ((txt(e) == "{" || txt(e) == "(" || txt(e) == "[") && info[e].match != std::string::npos) {
                            for (std::size_t q = e; q <= info[e].match; ++q) info[q].constant = true;
                            e = info[e].match;
                        }
                        info[e].constant = true;
                        ++e;
                    }
                    k = e;
                }
            }
        }
    }

    // 3. Helpers over the token stream.
    auto operand_end = [&](std::size_t i) {  // can token i end an operand (so the next operator is binary)?
        if (i >= n) return false;
        const Token& t = tokens_[i];
        if (t.kind == TokenKind::number || t.kind == TokenKind::string) return true;
        if (t.kind == TokenKind::identifier)
            return !keywords().count(t.text) || t.text == "this" || t.text == "true" || t.text == "false" ||
                   t.text == "nullptr";
        if (t.text == "]") return true;
        if (t.text == ")") {  // not the condition of if/while/for/switch: "if (p) *p = 0" dereferences
            const std::size_t open = info[i].match;
            if (open == std::string::npos || open == 0) return true;
            const std::string& k = txt(open - 1);
            return !(k == "if" || k == "while" || k == "for" || k == "switch" || k == "constexpr");
        }
        if ((t.text == "++" || t.text == "--") && i > 0) {
            const std::string& p = txt(i - 1);
            return p == ")" || p == "]" || (kind(i - 1) == TokenKind::identifier && !keywords().count(p));
        }
        return false;
    };
    auto typeish = [&](std::size_t i) {  // could token i end a type (for "T* name" and "T&& name")?
        if (i >= n) return false;
        const std::string& t = txt(i);
        if (info[i].template_close || type_words().count(t)) return true;
        return kind(i) == TokenKind::identifier && std::isupper(static_cast<unsigned char>(t[0]));
    };
    auto declaration_like = [&](std::size_t op) {  // "Type* name =", "Type&& name,"
        if (op == 0 || !typeish(op - 1) || kind(op + 1) != TokenKind::identifier) return false;
        const std::string& a = txt(op + 2);
        return a == "=" || a == "," || a == ")" || a == ";" || a == "[" || a == "{" || a == ":";
    };
    // The end (inclusive) of the right operand of a binary operator at `op` with the given stoppers.
    auto right_operand_end = [&](std::size_t op, bool stop_at_and) -> std::size_t {
        std::size_t j = op + 1;
        std::size_t last = std::string::npos;
        for (; j < n; ++j) {
            const std::string& t = txt(j);
            if ((t == "(" || t == "[" || t == "{" || (t == "<" && info[j].template_open)) &&
                info[j].match != std::string::npos) {
                j = info[j].match;
                last = j;
                continue;
            }
            if (t == ")" || t == "]" || t == "}" || t == ";" || t == "," || t == "?" || t == ":" || t == "||" ||
                (stop_at_and && t == "&&") || t == "=" || t == "+=" || t == "-=" || t == "*=" || t == "/=" ||
                t == "%=" || t == "&=" || t == "|=" || t == "^=" || t == "<<=" || t == ">>=" || t == "...")
                break;
            last = j;
        }
        return last;
    };
    // The start of the postfix expression that ends just before token `dot` (".", "->" or "::").
    auto postfix_start = [&](std::size_t dot) -> std::size_t {
        std::size_t j = dot;
        for (;;) {
            if (j == 0) return j;
            std::size_t p = j - 1;
            // calls, subscripts and template arguments before the operand's name
            while ((txt(p) == ")" || txt(p) == "]" || info[p].template_close) && info[p].match != std::string::npos) {
                j = info[p].match;
                if (j == 0) return j;
                p = j - 1;
                if (!(txt(p) == ")" || txt(p) == "]" || info[p].template_close ||
                      (kind(p) == TokenKind::identifier && (!keywords().count(txt(p)) || txt(p) == "this"))))
                    return j;
            }
            if (kind(p) == TokenKind::identifier && (!keywords().count(txt(p)) || txt(p) == "this")) j = p;
            else return j;
            if (j > 0 && (txt(j - 1) == "." || txt(j - 1) == "->" || txt(j - 1) == "::")) {
                j = j - 1;
                continue;
            }
            return j;
        }
    };
    // The block that a control statement or brace at token i belongs to: is `i` directly governed by
    // if/else/for/while/do/switch/case (so dropping a statement there is a plausible bug)?
    auto governed_by_control = [&](std::size_t stmt) {
        if (stmt == 0) return false;
        std::size_t p = stmt - 1;
        auto control_before = [&](std::size_t q) {
            const std::string& t = txt(q);
            if (t == "else" || t == "do") return true;
            if (t == ":") return true;  // a case label
            if (t == ")" && info[q].match != std::string::npos && info[q].match > 0) {
                std::size_t o = info[q].match - 1;
                if (txt(o) == "constexpr" && o > 0) --o;
                const std::string& k = txt(o);
                return k == "if" || k == "for" || k == "while" || k == "switch";
            }
            return false;
        };
        if (control_before(p)) return true;  // an unbraced sub-statement
        // Otherwise the innermost enclosing '{' and what precedes it.
        int depth = 0;
        for (std::size_t q = stmt; q-- > 0;) {
            const std::string& t = txt(q);
            if (t == "}") ++depth;
            else if (t == "{") {
                if (depth == 0) return q > 0 && control_before(q - 1);
                --depth;
            }
        }
        return false;
    };

    // 4. The sites.
    int next_id = first_id;
    auto add = [&](Site site, const std::vector<std::string>& mutated, const std::vector<std::string>& replacements,
                   const std::string& original, const std::string& mkind, std::size_t edit_first, std::size_t edit_last,
                   bool schema_ok) {
        const Token& at = tokens_[site.tok];
        for (std::size_t k = 0; k < mutated.size(); ++k) {
            Mutant m;
            m.id = next_id++;
            m.file = file_;
            m.line = at.line;
            m.col = at.col;
            m.kind = mkind;
            m.original = original;
            m.mutated = mutated[k];
            m.offset = tokens_[edit_first].offset;
            m.length = tokens_[edit_last].offset + tokens_[edit_last].length - m.offset;
            m.replacement = replacements[k];
            m.schema_ok = schema_ok;
            m.needs_relax = !schema_ok && info[site.tok].constant && !info[site.tok].hard;
            m.array_bound = info[site.tok].array_bound;
            site.ids.push_back(m.id);
            mutants_.push_back(std::move(m));
        }
        sites_.push_back(std::move(site));
    };
    for (std::size_t i = 0; i < n; ++i) {
        const TokenInfo& ti = info[i];
        if (!ti.in_solution || ti.in_template_args || ti.unevaluated) continue;
        const Token& t = tokens_[i];
        const bool constant = ti.constant;
        const bool binary = i > 0 && operand_end(i - 1);
        const std::string& prev = i > 0 ? txt(i - 1) : txt(n);
        if (t.kind == TokenKind::punct) {
            if (prev == "operator") continue;
            const std::string& op = t.text;
            if ((op == "<" && !ti.template_open) || (op == ">" && !ti.template_close) || op == "<=" ||
                (op == ">=" && !ti.template_close) || op == "==" || op == "!=" || op == "+" || op == "-" ||
                op == "*" || op == "/") {
                if (!binary) {
                    // unary: a dropped minus
                    if (op == "-" && i + 1 < n && txt(i + 1) != "-" && txt(i + 1) != "!" && txt(i + 1) != "~" &&
                        txt(i + 1) != "+" && prev != "-" && prev != "!" && prev != "~" && prev != "+" && prev != "*" &&
                        prev != "&") {
                        Site s;
                        s.form = Form::prefix;
                        s.tok = s.first = s.last = i;
                        s.code = 1;
                        add(s, {"(dropped)"}, {""}, "-", "unary-minus", i, i, !constant);
                    }
                    continue;
                }
                if ((op == "*") && declaration_like(i)) continue;
                // "text" + s builds a message: its minus can only be stillborn
                if ((op == "+" || op == "-") && (kind(i - 1) == TokenKind::string || kind(i + 1) == TokenKind::string))
                    continue;
                Site s;
                s.form = Form::binop;
                s.tok = s.first = s.last = i;
                s.code = binop_code(op);
                const auto alts = binop_alternatives(op);
                add(s, alts, alts, op, kind_of(op), i, i, !constant);
            } else if (op == "!") {
                if (prev == "!" || prev == "-" || prev == "~" || prev == "*" || prev == "&" || i + 1 >= n) continue;
                Site s;
                s.form = Form::prefix;
                s.tok = s.first = s.last = i;
                s.code = 0;
                add(s, {"(dropped)"}, {""}, "!", "negation", i, i, !constant);
            } else if ((op == "&&" || op == "||") && binary && !declaration_like(i)) {
                const std::size_t r_end = right_operand_end(i, op == "&&");
                if (r_end == std::string::npos || r_end <= i) continue;
                Site s;
                s.form = Form::logical;
                s.tok = i;
                s.first = i + 1;
                s.last = r_end;
                s.code = op == "&&" ? 0 : 1;
                const std::string other = op == "&&" ? "||" : "&&";
                add(s, {other}, {other}, op, "logical", i, i, !constant);
            } else if ((op == "+=" || op == "-=") && binary) {
                const std::size_t r_end = right_operand_end(i, false);
                if (r_end == std::string::npos || r_end <= i) continue;
                Site s;
                s.form = Form::wrap;
                s.tok = i;
                s.first = i + 1;
                s.last = r_end;
                const std::string other = op == "+=" ? "-=" : "+=";
                add(s, {other}, {other}, op, "compound", i, i, !constant);
                sites_.back().prefix = "geolab_mutant_rt::negate_if<" + std::to_string(sites_.back().ids[0]) + ">((";
                sites_.back().suffix = "))";
            }
            continue;
        }
        if (t.kind == TokenKind::number) {
            const auto alts = literal_alternatives(t.text);
            if (alts.empty()) continue;
            Site s;
            s.form = Form::choice;
            s.tok = s.first = s.last = i;
            s.alts = alts;
            add(s, alts, alts, t.text, "constant", i, i, !constant);
            continue;
        }
        if (t.kind != TokenKind::identifier) continue;
        if ((t.text == "return" || t.text == "break" || t.text == "continue") && governed_by_control(i)) {
            std::size_t end = i;
            while (end < n && txt(end) != ";") {
                if ((txt(end) == "(" || txt(end) == "[" || txt(end) == "{") && info[end].match != std::string::npos)
                    end = info[end].match;
                ++end;
            }
            if (end >= n) continue;
            std::string stmt;
            for (std::size_t k = i; k <= end; ++k) {
                if (k > i && !(txt(k) == ";" || txt(k) == ")" || txt(k) == "," || txt(k) == "." || txt(k) == "->" ||
                               txt(k) == "(" || txt(k - 1) == "(" || txt(k - 1) == "." || txt(k - 1) == "->" ||
                               txt(k) == "[" || txt(k) == "]" || txt(k - 1) == "[" || txt(k) == "::" ||
                               txt(k - 1) == "::" || txt(k - 1) == "!"))
                    stmt += ' ';
                stmt += txt(k);
            }
            if (stmt.size() > 60) stmt = stmt.substr(0, 57) + "...";
            Site s;
            s.form = Form::wrap;
            s.tok = s.first = i;
            s.last = end;
            add(s, {"(dropped)"}, {";"}, stmt, "drop-" + t.text, i, end, !constant);
            sites_.back().prefix = "{ if (!geolab_mutant_rt::on(" + std::to_string(sites_.back().ids[0]) + ")) ";
            sites_.back().suffix = " }";
            continue;
        }
        auto sw = swaps().find(t.text);
        if (sw == swaps().end() ||
            (!vocab.identifiers.count(sw->second) && !(prev == "::" && i >= 2 && txt(i - 2) == "std")))
            continue;
        const bool member = prev == "." || prev == "->";
        const bool qualified = prev == "::";
        std::size_t call_end = std::string::npos;
        std::size_t after = i + 1;
        if (txt(after) == "<" && info[after].template_open && info[after].match != std::string::npos)
            after = info[after].match + 1;
        if (txt(after) == "(" && info[after].match != std::string::npos) call_end = info[after].match;
        const bool field = t.text == "first" || t.text == "second";
        if (field ? !member || call_end != std::string::npos : call_end == std::string::npos) continue;
        // an unqualified call min(a, b) is a site; "Type min(" declares a function
        if (!field && !member && !qualified && i > 0 &&
            ((kind(i - 1) == TokenKind::identifier && !keywords().count(prev)) || info[i - 1].template_close))
            continue;
        Site s;
        s.form = Form::choice;
        s.tok = i;
        s.first = (member || qualified) ? postfix_start(i - 1) : i;
        s.last = field ? i : call_end;
        s.alts = {sw->second};
        add(s, {sw->second}, {sw->second}, t.text, "swap", i, i, !constant);
    }
    // Ranges that cross (neither nested nor disjoint) cannot both be written into one schema: such sites are
    // rebuilt one mutant at a time.
    std::map<int, Mutant*> by_id;
    for (auto& m : mutants_) by_id[m.id] = &m;
    for (std::size_t a = 0; a < sites_.size(); ++a)
        for (std::size_t b = 0; b < sites_.size(); ++b) {
            const Site &x = sites_[a], &y = sites_[b];
            if (x.form == Form::binop || x.form == Form::prefix || y.form == Form::binop || y.form == Form::prefix) continue;
            if (x.first < y.first && y.first <= x.last && x.last < y.last)
                for (const Site* z : {&x, &y})
                    for (int id : z->ids) by_id[id]->schema_ok = false;
        }
}

std::string SourceFile::apply(const Mutant& m) const {
    std::string out = text_;
    out.replace(m.offset, m.length, m.replacement);
    return out;
}

// ---- the schema ---------------------------------------------------------------------------------------------

const std::string& schema_preamble() {
    static const std::string text = R"PRE(// geolab mutate: the mutant schema runtime (generated; see grading/mutate.hpp).
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <type_traits>
#include <fcntl.h>
#include <unistd.h>
#include <utility>
namespace geolab_mutant_rt {
// The selected mutant (GEOLAB_MUTANT), read once; -1: none.
inline long selected() {
    static const long id = [] {
        const char* s = std::getenv("GEOLAB_MUTANT");
        return s && *s ? std::atol(s) : -1L;
    }();
    return id;
}
// Coverage (GEOLAB_MUTANT_COVERAGE=file): every site reached appends its first mutant's id to the file, once.
// A test that never reaches a site cannot kill its mutants, so they are not run against it.
inline int coverage_fd() {
    static const int fd = [] {
        const char* p = std::getenv("GEOLAB_MUTANT_COVERAGE");
        return p && *p ? ::open(p, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644) : -1;
    }();
    return fd;
}
// Start-up: each schema file's last dynamic initializer calls started(first, last) with its mutants' ids. A site
// reached before that is reached while the file's tables (constexpr variables of a relaxed schema) are computed;
// the coverage writes it as -1 - k, a site reached later as k.
struct IdRange { long first, last; };
inline IdRange started_files[256];
inline std::atomic<int> n_started{0};
inline bool started(long first, long last) {
    const int i = n_started.load();
    if (i < 256) {
        started_files[i] = {first, last};
        n_started.store(i + 1);
    }
    return true;
}
inline bool past_startup(long k) {
    for (int i = 0, n = n_started.load(); i < n; ++i)
        if (k >= started_files[i].first && k <= started_files[i].last) return true;
    return false;
}
inline void reached(long k) {
    static std::atomic<unsigned char> seen[1 << 16];
    if (k < 0 || k >= (1 << 16)) return;
    const unsigned char phase = past_startup(k) ? 2 : 1;
    // a plain load first: sites in loops that several threads run are reached millions of times, and an atomic
    // read-modify-write each time would bounce the flag's cache line between the cores
    if ((seen[k].load(std::memory_order_relaxed) & phase) || (seen[k].fetch_or(phase) & phase)) return;
    char buf[32];
    const int n = std::snprintf(buf, sizeof buf, "%ld\n", phase == 2 ? k : -1 - k);
    (void)!::write(coverage_fd(), buf, static_cast<std::size_t>(n));
}
// A table of a relaxed schema, just computed: its size and FNV-1a digest appended to GEOLAB_MUTANT_TABLES. The
// same lines with a mutant selected prove that the mutant computes the same tables.
inline bool table(const void* p, std::size_t size) {
    const char* path = std::getenv("GEOLAB_MUTANT_TABLES");
    if (!path || !*path) return true;
    unsigned long long h = 14695981039346656037ull;
    for (std::size_t i = 0; i < size; ++i) {
        h ^= static_cast<const unsigned char*>(p)[i];
        h *= 1099511628211ull;
    }
    if (std::FILE* f = std::fopen(path, "a")) {
        std::fprintf(f, "%zu %016llx\n", size, h);
        std::fclose(f);
    }
    return true;
}
inline bool on(long k) {
    if (coverage_fd() >= 0) reached(k);
    return selected() == k;
}
// A mutant whose mutated expression does not type-check (stillborn), or has another type than the original
// (it needs a rebuild of its own): written at start-up to GEOLAB_MUTANT_REPORT, so the tool learns them.
inline bool report(long k, const char* what) {
    if (const char* path = std::getenv("GEOLAB_MUTANT_REPORT")) {
        if (std::FILE* f = std::fopen(path, "a")) {
            std::fprintf(f, "%ld %s\n", k, what);
            std::fclose(f);
        }
    }
    return true;
}
template <long K> struct Stillborn { static inline const bool reported = report(K, "stillborn"); };
template <long K> struct Rebuild { static inline const bool reported = report(K, "rebuild"); };

#define GEOLAB_MUTANT_OPS(X) X(0, <) X(1, <=) X(2, >) X(3, >=) X(4, ==) X(5, !=) X(6, +) X(7, -) X(8, *) X(9, /)
// Binary operator `op` at a site: "a op Bin<K, Code>() op b" groups exactly as "a op b". The mutants of the
// site are K (first alternative) and K + 1 (second one, for relational operators).
template <long K, int Code> struct Bin {};
template <class A, long K, int Code> struct BinLeft { A&& a; };
template <int Code, class A, class B> constexpr bool op_valid() {
#define X(c, o) if constexpr (Code == c) return requires(A&& a, B&& b) { std::forward<A>(a) o std::forward<B>(b); };
    GEOLAB_MUTANT_OPS(X)
#undef X
    return false;
}
template <int Code, class A, class B> decltype(auto) apply(A&& a, B&& b) {
#define X(c, o) if constexpr (Code == c) return std::forward<A>(a) o std::forward<B>(b); else
    GEOLAB_MUTANT_OPS(X)
#undef X
    return;
}
// Whether alternative Alt of Code can replace it for these operands: 0 yes, 1 it does not type-check
// (stillborn), 2 it has another type (the mutant needs a rebuild of its own).
template <int Code, int Alt, class A, class B> constexpr int usability() {
    if constexpr (!op_valid<Alt, A, B>()) return 1;
    else if constexpr (!std::is_same_v<decltype(apply<Code>(std::declval<A>(), std::declval<B>())),
                                       decltype(apply<Alt>(std::declval<A>(), std::declval<B>()))>)
        return 2;
    else return 0;
}
template <int Code> constexpr int alt1() { return Code == 0 ? 1 : Code == 1 ? 0 : Code == 2 ? 3 : Code == 3 ? 2 : Code == 4 ? 5 : Code == 5 ? 4 : Code == 6 ? 7 : Code == 7 ? 6 : Code == 8 ? 9 : 8; }
template <int Code> constexpr int alt2() { return Code == 0 ? 3 : Code == 1 ? 2 : Code == 2 ? 1 : Code == 3 ? 0 : -1; }
template <int Code, long K, class A, class B> decltype(auto) eval(BinLeft<A, K, Code>&& l, B&& b) {
    constexpr int u1 = usability<Code, alt1<Code>(), A, B>();
    if constexpr (u1 == 0) {
        if (on(K)) return apply<alt1<Code>()>(std::forward<A>(l.a), std::forward<B>(b));
    } else if constexpr (u1 == 1) {
        (void)Stillborn<K>::reported;
    } else {
        (void)Rebuild<K>::reported;
    }
    if constexpr (alt2<Code>() >= 0) {
        constexpr int u2 = usability<Code, alt2<Code>(), A, B>();
        if constexpr (u2 == 0) {
            if (on(K + 1)) return apply<alt2<Code>()>(std::forward<A>(l.a), std::forward<B>(b));
        } else if constexpr (u2 == 1) {
            (void)Stillborn<K + 1>::reported;
        } else {
            (void)Rebuild<K + 1>::reported;
        }
    }
    return apply<Code>(std::forward<A>(l.a), std::forward<B>(b));
}
#define X(c, o)                                                                                             \
    template <class A, long K> BinLeft<A, K, c> operator o(A&& a, Bin<K, c>) { return {std::forward<A>(a)}; } \
    template <class A, long K, class B> decltype(auto) operator o(BinLeft<A, K, c>&& l, B&& b) {             \
        return eval<c>(std::move(l), std::forward<B>(b));                                                    \
    }
GEOLAB_MUTANT_OPS(X)
#undef X
#undef GEOLAB_MUTANT_OPS

// A dropped unary operator: "Un<K, 0>() ->* x" is !x, or bool(x) under mutant K; "Un<K, 1>() ->* x" is -x or x.
template <long K, int Code> struct Un {};
template <long K, class T> bool operator->*(Un<K, 0>, T&& x) {
    if constexpr (requires { static_cast<bool>(x); }) {
        if (on(K)) return static_cast<bool>(x);
    } else {
        (void)Stillborn<K>::reported;
    }
    return !x;
}
template <long K, class T> auto operator->*(Un<K, 1>, T&& x) -> decltype(-x) {
    if constexpr (std::is_same_v<std::remove_cvref_t<T>, std::remove_cvref_t<decltype(-x)>>) {
        if (on(K)) return x;
    } else if constexpr (requires { static_cast<decltype(-x)>(x); }) {
        (void)Rebuild<K>::reported;
    } else {
        (void)Stillborn<K>::reported;
    }
    return -x;
}

// && and ||: "a && Logic<K, 0>() && [&]() -> bool { return bool(b); }" keeps the short circuit of both.
template <long K, int Code> struct Logic {};
template <long K, int Code> struct LogicLeft { bool a; };
template <class A, long K> LogicLeft<K, 0> operator&&(A&& a, Logic<K, 0>) { return {static_cast<bool>(a)}; }
template <class A, long K> LogicLeft<K, 1> operator||(A&& a, Logic<K, 1>) { return {static_cast<bool>(a)}; }
template <long K, class F> bool operator&&(LogicLeft<K, 0> l, F&& b) { return on(K) ? (l.a || b()) : (l.a && b()); }
template <long K, class F> bool operator||(LogicLeft<K, 1> l, F&& b) { return on(K) ? (l.a && b()) : (l.a || b()); }

// += <-> -=: "a += negate_if<K>((b))".
template <long K, class T> std::remove_cvref_t<T> negate_if(T&& x) {
    using R = std::remove_cvref_t<T>;
    if constexpr (requires { static_cast<R>(-x); }) {
        if (on(K)) return static_cast<R>(-x);
    } else {
        (void)Stillborn<K>::reported;
    }
    return std::forward<T>(x);
}
}  // namespace geolab_mutant_rt
#define GEOLAB_MUTANT_RELAXED_STATIC_ASSERT(...) static_assert(true)
)PRE";
    return text;
}

std::string SourceFile::schema(const std::set<int>& ids, std::vector<Span>* spans, bool relax) const {
    // The edits of the selected sites, indexed by token.
    struct Wrap {
        std::size_t first, last;
        std::string prefix, suffix;
        std::vector<int> ids;
    };
    const std::size_t n = tokens_.size();
    std::vector<std::vector<std::size_t>> wraps_at(n), choices_at(n);
    std::vector<Wrap> wraps;
    std::vector<const Site*> choices;
    std::map<std::size_t, std::pair<std::string, std::vector<int>>> replace;  // token -> text, ids
    auto rt = std::string("geolab_mutant_rt::");
    for (const Site& s : sites_) {
        std::vector<int> chosen;
        for (int id : s.ids)
            if (ids.count(id)) chosen.push_back(id);
        if (chosen.empty()) continue;
        const std::string k0 = std::to_string(s.ids[0]);
        switch (s.form) {
            case Form::binop:  // the site's mutants are K and K + 1 (relational operators have two)
                replace[s.tok] = {tokens_[s.tok].text + " " + rt + "Bin<" + k0 + ", " + std::to_string(s.code) + ">() " +
                                      tokens_[s.tok].text,
                                  chosen};
                break;
            case Form::prefix:
                replace[s.tok] = {rt + "Un<" + k0 + ", " + std::to_string(s.code) + ">() ->*", chosen};
                break;
            case Form::logical:
                replace[s.tok] = {tokens_[s.tok].text + " " + rt + "Logic<" + k0 + ", " + std::to_string(s.code) +
                                      ">() " + tokens_[s.tok].text,
                                  chosen};
                wraps.push_back({s.first, s.last, "[&]() -> bool { return static_cast<bool>(", "); }", chosen});
                break;
            case Form::wrap:
                wraps.push_back({s.first, s.last, s.prefix, s.suffix, chosen});
                break;
            case Form::choice:
                choices.push_back(&s);
                break;
        }
    }
    std::map<std::size_t, std::string> append;  // token -> text written after it
    if (relax) {
        for (const auto& [t, text] : relax_tokens_) replace[t] = {text, {}};
        for (const Table& tab : tables_)
            for (std::size_t k = 0; k < tab.names.size(); ++k)
                append[tab.end] += " static const bool geolab_mutant_table_" + std::to_string(tab.end) + "_" +
                                   std::to_string(k) + " = " + rt + "table(&" + tab.names[k] + ", sizeof(" +
                                   tab.names[k] + "));";
    }
    for (std::size_t w = 0; w < wraps.size(); ++w) wraps_at[wraps[w].first].push_back(w);
    for (std::size_t c = 0; c < choices.size(); ++c) choices_at[choices[c]->first].push_back(c);
    for (auto& v : wraps_at)  // outer (longer) first
        std::sort(v.begin(), v.end(), [&](std::size_t a, std::size_t b) { return wraps[a].last > wraps[b].last; });
    for (auto& v : choices_at)
        std::sort(v.begin(), v.end(), [&](std::size_t a, std::size_t b) { return choices[a]->last > choices[b]->last; });
    std::vector<std::vector<std::size_t>> wraps_end(n);
    for (std::size_t w = 0; w < wraps.size(); ++w) wraps_end[wraps[w].last].push_back(w);
    for (auto& v : wraps_end)  // inner (later start) first
        std::sort(v.begin(), v.end(), [&](std::size_t a, std::size_t b) { return wraps[a].first > wraps[b].first; });

    std::string out = schema_preamble();
    int line = 1 + static_cast<int>(std::count(out.begin(), out.end(), '\n')), col = 1;
    auto emit = [&](const std::string& s) {
        for (char c : s) {
            if (c == '\n') {
                ++line;
                col = 1;
            } else {
                ++col;
            }
        }
        out += s;
    };
    auto emit_for = [&](const std::vector<int>& mids, const std::string& s) {
        const int l = line, c0 = col;
        emit(s);
        if (spans)
            for (int id : mids) spans->push_back({id, l, c0, line == l ? std::max(c0, col - 1) : 100000});
    };
    std::vector<char> busy(choices.size(), 0);
    // Emit tokens [s, e] and the text between them; `over` replaces one token's text (a choice's mutant).
    std::function<void(std::size_t, std::size_t, std::size_t, const std::string*)> render =
        [&](std::size_t s, std::size_t e, std::size_t over_tok, const std::string* over) {
            for (std::size_t i = s; i <= e; ++i) {
                // a choice starting here (the outermost one not being rendered already)
                std::size_t pick = std::string::npos;
                for (std::size_t c : choices_at[i])
                    if (!busy[c] && choices[c]->last <= e) {
                        pick = c;
                        break;
                    }
                if (pick != std::string::npos) {
                    const Site& c = *choices[pick];
                    for (std::size_t w : wraps_at[i])
                        if (wraps[w].last > c.last && wraps[w].last <= e) emit_for(wraps[w].ids, wraps[w].prefix);
                    busy[pick] = 1;
                    emit("(");
                    for (std::size_t k = 0; k < c.ids.size(); ++k) {
                        if (!ids.count(c.ids[k])) continue;
                        const int l0 = line, c0 = col;
                        emit(rt + "on(" + std::to_string(c.ids[k]) + ") ? (");
                        render(c.first, c.last, c.tok, &c.alts[k]);
                        emit(") : ");
                        if (spans) spans->push_back({c.ids[k], l0, c0, line == l0 ? col - 1 : 100000});
                    }
                    emit("(");
                    render(c.first, c.last, over_tok, over);
                    emit("))");
                    busy[pick] = 0;
                    for (std::size_t w : wraps_end[c.last])
                        if (wraps[w].first < c.first && wraps[w].first >= s) emit_for(wraps[w].ids, wraps[w].suffix);
                    i = c.last;
                } else {
                    for (std::size_t w : wraps_at[i])
                        if (wraps[w].last <= e) emit_for(wraps[w].ids, wraps[w].prefix);
                    auto r = replace.find(i);
                    if (i == over_tok && over) emit(*over);
                    else if (r != replace.end()) emit_for(r->second.second, r->second.first);
                    else emit(tokens_[i].text);
                    if (auto a = append.find(i); a != append.end()) emit(a->second);
                    for (std::size_t w : wraps_end[i])
                        if (wraps[w].first >= s) emit_for(wraps[w].ids, wraps[w].suffix);
                }
                if (i < e) emit(text_.substr(tokens_[i].offset + tokens_[i].length,
                                             tokens_[i + 1].offset - tokens_[i].offset - tokens_[i].length));
            }
        };
    // The text before the first code token, the tokens, and the text after the last one; preprocessor lines and
    // comments between tokens are copied with the gaps.
    if (n == 0) return out + text_;
    emit(text_.substr(0, tokens_[0].offset));
    render(0, n - 1, std::string::npos, nullptr);
    emit(text_.substr(tokens_[n - 1].offset + tokens_[n - 1].length));
    // the file's last dynamic initializer: its sites reached from now on are reached past its start-up
    if (!mutants_.empty())
        emit("\nstatic const bool geolab_mutant_started = " + rt + "started(" + std::to_string(first_id_) + ", " +
             std::to_string(first_id_ + static_cast<int>(mutants_.size()) - 1) + ");\n");
    return out;
}

}  // namespace geolab::grading::mutate
