#include "geolab/scad.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>

#include <glm/matrix.hpp>

#include "geolab/errors.hpp"
#include "geolab/io.hpp"

namespace geolab::scad {

ParseError::ParseError(const std::string& name, int line_, int column_, const std::string& message)
    : std::runtime_error(name + ":" + std::to_string(line_) + ":" + std::to_string(column_) + ": " + message),
      line(line_), column(column_) {}

namespace {

constexpr int max_depth = 256;
constexpr std::size_t max_solids = 1'000'000;
constexpr std::size_t max_vector = 1024;
// Vector entries that arithmetic may create in one file. A variable is shared, not copied, when used, but `a + a`
// on a 1000-vector makes 1000 entries from 3 bytes: without a budget a few kilobytes of `+` would take seconds and
// nested vectors of variables gigabytes. Real scenes use a handful of 3- and 4-vectors per solid.
constexpr std::size_t max_computed = 1'000'000;

enum class Tok { end, number, ident, punct };

struct Token {
    Tok kind = Tok::end;
    std::string text;  // identifier or punctuation
    double number = 0;
    int line = 1, column = 1;
};

// A value: a number, a boolean or a vector of values. A vector's entries are shared and never changed, so that
// copying a value (using a variable) costs O(1) whatever its size.
struct Value {
    enum Type { number, boolean, vector } type = number;
    double x = 0;
    std::shared_ptr<const std::vector<Value>> list;  // vector: the entries
    const std::vector<Value>& items() const {
        static const std::vector<Value> none;
        return list ? *list : none;
    }
    static Value of(std::vector<Value> entries) {
        Value v;
        v.type = vector;
        v.list = std::make_shared<const std::vector<Value>>(std::move(entries));
        return v;
    }
};

class Parser {
public:
    Parser(std::string_view text, const std::string& name) : s_(text), name_(name) {
        if (s_.starts_with("\xEF\xBB\xBF")) pos_ = 3;  // a UTF-8 byte order mark, as in every reader of lib
        next();
    }

    Scene run() {
        std::vector<int> top;
        while (tok_.kind != Tok::end) statement(glm::dmat4(1.0), top, 0);
        const int root = group(Kind::unite, top, 1, 1);
        if (root < 0) throw ParseError(name_, 1, 1, "the scene has no solid (nothing to draw)");
        scene_.root = root;
        return std::move(scene_);
    }

private:
    std::string_view s_;
    std::string name_;
    std::size_t pos_ = 0;
    int line_ = 1, col_ = 1;
    Token tok_;
    Scene scene_;
    std::size_t solids_ = 0;
    std::size_t computed_ = 0;  // vector entries made by arithmetic so far (max_computed)
    std::map<std::string, Value> vars_;

    [[noreturn]] void fail(const Token& t, const std::string& msg) const {
        throw ParseError(name_, t.line, t.column, msg);
    }

    // ---- lexer ----
    char peekc(std::size_t k = 0) const { return pos_ + k < s_.size() ? s_[pos_ + k] : '\0'; }
    // A line ends with LF, CRLF or a lone CR (old Mac files), as in every reader of lib.
    void advance() {
        if (s_[pos_] == '\n' || (s_[pos_] == '\r' && peekc(1) != '\n')) {
            ++line_;
            col_ = 1;
        } else if (s_[pos_] == '\r') {
            // CR of a CRLF: the LF ends the line
        } else if ((static_cast<unsigned char>(s_[pos_]) & 0xC0) != 0x80) {
            ++col_;  // count UTF-8 characters, not bytes
        }
        ++pos_;
    }
    void next() {
        for (;;) {  // whitespace and comments
            while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) advance();
            if (peekc() == '/' && peekc(1) == '/') {
                while (pos_ < s_.size() && s_[pos_] != '\n' && s_[pos_] != '\r') advance();
            } else if (peekc() == '/' && peekc(1) == '*') {
                const int l = line_, c = col_;
                advance();
                advance();
                while (pos_ < s_.size() && !(peekc() == '*' && peekc(1) == '/')) advance();
                if (pos_ >= s_.size()) throw ParseError(name_, l, c, "comment '/*' is never closed");
                advance();
                advance();
            } else {
                break;
            }
        }
        tok_ = Token{};
        tok_.line = line_;
        tok_.column = col_;
        if (pos_ >= s_.size()) return;
        const char c = s_[pos_];
        if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && std::isdigit(static_cast<unsigned char>(peekc(1))))) {
            const std::size_t start = pos_;
            while (std::isdigit(static_cast<unsigned char>(peekc())) || peekc() == '.') advance();
            if (peekc() == 'e' || peekc() == 'E') {
                advance();
                if (peekc() == '+' || peekc() == '-') advance();
                if (!std::isdigit(static_cast<unsigned char>(peekc()))) fail(tok_, "malformed number");
                while (std::isdigit(static_cast<unsigned char>(peekc()))) advance();
            }
            const std::string text(s_.substr(start, pos_ - start));
            if (std::count(text.begin(), text.end(), '.') > 1) fail(tok_, "malformed number '" + text + "'");
            tok_.kind = Tok::number;
            tok_.text = text;
            tok_.number = std::strtod(text.c_str(), nullptr);
            if (!std::isfinite(tok_.number)) fail(tok_, "number '" + text.substr(0, 40) + "' is not finite");
            return;
        }
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '$') {
            const std::size_t start = pos_;
            advance();
            while (std::isalnum(static_cast<unsigned char>(peekc())) || peekc() == '_') advance();
            tok_.kind = Tok::ident;
            tok_.text = std::string(s_.substr(start, pos_ - start));
            if (tok_.text.size() > 200) fail(tok_, "identifier longer than 200 characters");
            return;
        }
        tok_.kind = Tok::punct;
        // Two-character operators are not in the subset; report them whole so the message names them.
        static const char* two[] = {"==", "!=", "<=", ">=", "&&", "||"};
        for (const char* t : two)
            if (c == t[0] && peekc(1) == t[1]) {
                tok_.text = t;
                advance();
                advance();
                return;
            }
        if ((static_cast<unsigned char>(c) & 0x80) != 0) {
            tok_.text = "non-ASCII character";
            advance();
            return;
        }
        if (static_cast<unsigned char>(c) < 32 || c == 127) {  // named, not printed raw into the message
            char hex[8];
            std::snprintf(hex, sizeof hex, "%02X", static_cast<unsigned>(static_cast<unsigned char>(c)));
            tok_.text = std::string("control character 0x") + hex;
            advance();
            return;
        }
        tok_.text = std::string(1, c);
        advance();
    }
    bool is(const char* p) const { return tok_.kind == Tok::punct && tok_.text == p; }
    void expect(const char* p, const std::string& where) {
        if (!is(p)) fail(tok_, std::string("expected '") + p + "' " + where + ", found " + describe(tok_));
        next();
    }
    static std::string describe(const Token& t) {
        switch (t.kind) {
            case Tok::end: return "the end of the file";
            case Tok::number: return "the number " + t.text.substr(0, 40);
            case Tok::ident: return "'" + t.text + "'";
            case Tok::punct: return t.text.size() == 1 || t.text.size() == 2 ? "'" + t.text + "'" : t.text;
        }
        return "?";
    }

    // ---- expressions ----
    Value expr(int depth) {
        if (depth > max_depth) fail(tok_, "expression nested deeper than " + std::to_string(max_depth));
        Value v = term(depth);
        while (is("+") || is("-")) {
            const Token op = tok_;
            next();
            v = arith(op, v, term(depth));
        }
        if (is("?")) fail(tok_, "the conditional operator '?' is not in the supported subset");
        if (is("==") || is("!=") || is("<") || is(">") || is("<=") || is(">=") || is("&&") || is("||"))
            fail(tok_, "operator " + describe(tok_) + " is not in the supported subset");
        return v;
    }
    Value term(int depth) {
        Value v = unary(depth);
        while (is("*") || is("/") || is("%")) {
            const Token op = tok_;
            if (op.text == "%") fail(op, "operator '%' is not in the supported subset");
            next();
            v = arith(op, v, unary(depth));
        }
        return v;
    }
    Value unary(int depth) {
        if (depth > max_depth) fail(tok_, "expression nested deeper than " + std::to_string(max_depth));
        if (is("-") || is("+")) {
            const Token op = tok_;
            next();
            Value v = unary(depth + 1);
            if (op.text == "-") v = negate(op, v);
            return v;
        }
        return primary(depth);
    }
    // Counts `n` vector entries made by arithmetic against max_computed.
    void compute(std::size_t n, const Token& at) {
        computed_ += n;
        if (computed_ > max_computed)
            fail(at, "the expressions compute more than " + std::to_string(max_computed) +
                         " vector entries (vectors of vectors in arithmetic?)");
    }
    Value negate(const Token& at, const Value& v) {
        if (v.type == Value::boolean) fail(at, "cannot negate a boolean");
        if (v.type == Value::number) return Value{Value::number, -v.x, {}};
        compute(v.items().size(), at);
        std::vector<Value> r;
        r.reserve(v.items().size());
        for (const Value& e : v.items()) r.push_back(negate(at, e));
        return Value::of(std::move(r));
    }
    Value primary(int depth) {
        const Token t = tok_;
        if (t.kind == Tok::number) {
            next();
            return Value{Value::number, t.number, {}};
        }
        if (is("(")) {
            next();
            Value v = expr(depth + 1);
            expect(")", "to close '('");
            return v;
        }
        if (is("[")) {
            next();
            std::vector<Value> items;
            if (!is("]")) {
                for (;;) {
                    if (items.size() >= max_vector) fail(t, "vector longer than " + std::to_string(max_vector));
                    items.push_back(expr(depth + 1));
                    if (is(":")) fail(tok_, "ranges '[a : b]' are not in the supported subset");
                    if (!is(",")) break;
                    next();
                }
            }
            expect("]", "to close the vector");
            return Value::of(std::move(items));
        }
        if (t.kind == Tok::ident) {
            next();
            if (is("(")) fail(t, "function call '" + t.text + "(...)' is not in the supported subset");
            if (t.text == "true" || t.text == "false") return Value{Value::boolean, t.text == "true" ? 1.0 : 0.0, {}};
            if (t.text == "PI") return Value{Value::number, std::numbers::pi, {}};
            const auto it = vars_.find(t.text);
            if (it == vars_.end()) fail(t, "unknown variable '" + t.text + "' (assign it before use)");
            return it->second;
        }
        fail(t, "expected a value, found " + describe(t));
    }
    Value arith(const Token& op, const Value& a, const Value& b) {
        const char o = op.text[0];
        if (a.type == Value::boolean || b.type == Value::boolean)
            fail(op, std::string("arithmetic '") + o + "' on a boolean");
        Value r;
        if (a.type == Value::number && b.type == Value::number) {
            r.x = o == '+' ? a.x + b.x : o == '-' ? a.x - b.x : o == '*' ? a.x * b.x : a.x / b.x;
            if (!std::isfinite(r.x)) fail(op, std::string("'") + o + "' gives a value that is not finite");
            return r;
        }
        std::vector<Value> items;
        if (a.type == Value::vector && b.type == Value::vector) {
            if (o != '+' && o != '-') fail(op, std::string("vector ") + o + " vector is not in the supported subset");
            if (a.items().size() != b.items().size()) fail(op, "vectors of different lengths");
            compute(a.items().size(), op);
            items.reserve(a.items().size());
            for (std::size_t i = 0; i < a.items().size(); ++i) items.push_back(arith(op, a.items()[i], b.items()[i]));
            return Value::of(std::move(items));
        }
        if (o == '+' || o == '-') fail(op, std::string("number ") + o + " vector is not in the supported subset");
        if (a.type == Value::vector && o == '/') {
            compute(a.items().size(), op);
            items.reserve(a.items().size());
            for (const Value& e : a.items()) items.push_back(arith(op, e, b));
            return Value::of(std::move(items));
        }
        if (o == '/') fail(op, "number / vector is not in the supported subset");
        const Value& v = a.type == Value::vector ? a : b;
        const Value& s = a.type == Value::vector ? b : a;
        compute(v.items().size(), op);
        items.reserve(v.items().size());
        for (const Value& e : v.items()) items.push_back(arith(op, s, e));
        return Value::of(std::move(items));
    }

    // ---- arguments ----
    struct Arg {
        std::string name;  // empty: positional
        Value value;
        Token at;
    };
    std::vector<Arg> arguments() {
        expect("(", "after the module name");
        std::vector<Arg> args;
        while (!is(")")) {
            Arg a;
            a.at = tok_;
            if (tok_.kind == Tok::ident) {
                // name = value, or a value that starts with an identifier
                const std::size_t p = pos_;
                const int l = line_, c = col_;
                const Token save = tok_;
                next();
                if (is("=")) {
                    a.name = save.text;
                    next();
                } else {
                    pos_ = p;
                    line_ = l;
                    col_ = c;
                    tok_ = save;
                }
            }
            a.value = expr(0);
            if (args.size() >= 64) fail(a.at, "more than 64 arguments");
            args.push_back(std::move(a));
            if (!is(",")) break;
            next();
        }
        expect(")", "to close the argument list");
        return args;
    }
    double number_of(const Arg& a, const std::string& what) {
        if (a.value.type != Value::number) fail(a.at, what + " must be a number");
        return a.value.x;
    }
    glm::dvec3 vec3_of(const Arg& a, const std::string& what, bool allow_2 = false) {
        const Value& v = a.value;
        if (v.type != Value::vector || !(v.items().size() == 3 || (allow_2 && v.items().size() == 2)))
            fail(a.at, what + " must be a vector [x, y, z]");
        glm::dvec3 r(0.0);
        for (std::size_t i = 0; i < v.items().size(); ++i) {
            if (v.items()[i].type != Value::number) fail(a.at, what + " must hold numbers");
            r[int(i)] = v.items()[i].x;
        }
        return r;
    }
    bool bool_of(const Arg& a, const std::string& what) {
        if (a.value.type != Value::boolean) fail(a.at, what + " must be true or false");
        return a.value.x != 0;
    }
    // Binds named and positional arguments to `names` (in positional order); unknown ones are an error.
    std::map<std::string, const Arg*> bind(const Token& module, const std::vector<Arg>& args,
                                           const std::vector<std::string>& names) {
        std::map<std::string, const Arg*> out;
        std::size_t position = 0;
        for (const Arg& a : args) {
            std::string n = a.name;
            if (n == "$fn" || n == "$fa" || n == "$fs") continue;  // documented: ignored
            if (n.empty()) {
                if (position >= names.size())
                    fail(a.at, "too many arguments to '" + module.text + "' (" + std::to_string(names.size()) +
                                   " at most)");
                n = names[position++];
            } else if (std::find(names.begin(), names.end(), n) == names.end()) {
                fail(a.at, "argument '" + n + "' of '" + module.text + "' is not in the supported subset");
            }
            if (out.count(n)) fail(a.at, "argument '" + n + "' given twice");
            out[n] = &a;
        }
        return out;
    }

    // ---- statements ----
    int add(Node n) {
        scene_.nodes.push_back(std::move(n));
        return int(scene_.nodes.size()) - 1;
    }
    // A boolean over `kids`: none → -1 (nothing), one → that child, else a new node.
    int group(Kind k, const std::vector<int>& kids, int line, int column) {
        if (kids.empty()) return -1;
        if (kids.size() == 1) return kids[0];
        Node n;
        n.kind = k;
        n.children = kids;
        n.line = line;
        n.column = column;
        return add(std::move(n));
    }
    void check_depth(int depth) {
        if (depth > max_depth) fail(tok_, "statements nested deeper than " + std::to_string(max_depth));
    }

    // One statement; the solids it makes (transformed by M) are appended to `out` (at most one index).
    void statement(const glm::dmat4& M, std::vector<int>& out, int depth) {
        check_depth(depth);
        const Token t = tok_;
        if (is(";")) {
            next();
            return;
        }
        if (is("{")) {
            next();
            std::vector<int> kids;
            while (!is("}")) {
                if (tok_.kind == Tok::end) fail(t, "'{' is never closed");
                statement(M, kids, depth + 1);
            }
            next();
            const int g = group(Kind::unite, kids, t.line, t.column);
            if (g >= 0) out.push_back(g);
            return;
        }
        if (is("!") || is("#") || is("%") || is("*")) fail(t, "modifier '" + t.text + "' is not in the supported subset");
        if (t.kind != Tok::ident) fail(t, "expected a statement, found " + describe(t));
        next();
        if (is("=")) {
            next();
            Value v = expr(0);
            expect(";", "after the assignment");
            if (t.text.starts_with("$")) return;  // $fn = ...: ignored
            if (vars_.count(t.text))
                fail(t, "variable '" + t.text + "' assigned twice (OpenSCAD would use the last value everywhere; "
                        "not supported)");
            vars_[t.text] = std::move(v);
            return;
        }
        const std::string& m = t.text;
        static const char* unsupported[] = {"module", "function", "for", "if", "else", "let", "each", "echo",
                                            "assert", "include", "use", "import", "children", "intersection_for"};
        for (const char* u : unsupported)
            if (m == u) fail(t, "'" + m + "' is not in the supported subset");
        if (m == "cube" || m == "sphere" || m == "cylinder") {
            const auto args = arguments();
            expect(";", "after " + m + "(...)");
            if (++solids_ > max_solids) fail(t, "more than 1,000,000 solids");
            out.push_back(solid(t, args, M));
            return;
        }
        if (m == "union" || m == "difference" || m == "intersection") {
            const auto args = arguments();
            if (!args.empty()) fail(args[0].at, "'" + m + "()' takes no arguments");
            std::vector<int> kids;
            children(M, kids, depth);
            if (m == "union") {
                const int g = group(Kind::unite, kids, t.line, t.column);
                if (g >= 0) out.push_back(g);
            } else if (m == "intersection") {
                const int g = group(Kind::intersection, kids, t.line, t.column);
                if (g >= 0) out.push_back(g);
            } else if (!first_empty_ && !kids.empty()) {
                out.push_back(kids.size() == 1 ? kids[0] : group(Kind::difference, kids, t.line, t.column));
            }
            return;
        }
        static const char* transforms[] = {"translate", "rotate", "scale", "mirror", "multmatrix"};
        if (std::find_if(std::begin(transforms), std::end(transforms), [&](const char* x) { return m == x; }) !=
            std::end(transforms)) {
            const auto args = arguments();
            const glm::dmat4 T = transform(t, args);
            std::vector<int> kids;
            children(M * T, kids, depth);
            const int g = group(Kind::unite, kids, t.line, t.column);
            if (g >= 0) out.push_back(g);
            return;
        }
        fail(t, "module '" + m + "' is not in the supported subset");
    }

    bool first_empty_ = false;  // set by children(): the first child statement made no solid
    // The child of a transform or boolean: one statement, or a block whose statements are the children.
    void children(const glm::dmat4& M, std::vector<int>& kids, int depth) {
        check_depth(depth);
        bool first_empty = false;
        if (is("{")) {
            const Token open = tok_;
            next();
            bool first = true;
            while (!is("}")) {
                if (tok_.kind == Tok::end) fail(open, "'{' is never closed");
                const std::size_t before = kids.size();
                const bool counts = !is(";") && !(tok_.kind == Tok::ident && peek_is_assignment());
                statement(M, kids, depth + 1);
                if (counts && first) {
                    first_empty = kids.size() == before;
                    first = false;
                }
            }
            next();
        } else {
            const std::size_t before = kids.size();
            statement(M, kids, depth + 1);
            first_empty = kids.size() == before;
        }
        first_empty_ = first_empty;
    }
    bool peek_is_assignment() {
        std::size_t p = pos_;
        while (p < s_.size() && std::isspace(static_cast<unsigned char>(s_[p]))) ++p;
        return p < s_.size() && s_[p] == '=' && !(p + 1 < s_.size() && s_[p + 1] == '=');
    }

    int solid(const Token& t, const std::vector<Arg>& args, const glm::dmat4& M) {
        Node n;
        n.M = M;
        n.line = t.line;
        n.column = t.column;
        auto positive = [&](const Arg* a, double v, const std::string& what) {
            if (!(v > 0)) fail(a ? a->at : t, what + " must be > 0 (got " + std::to_string(v) + ")");
        };
        if (t.text == "cube") {
            const auto b = bind(t, args, {"size", "center"});
            n.kind = Kind::cube;
            if (b.count("size")) {
                const Arg* a = b.at("size");
                n.size = a->value.type == Value::number ? glm::dvec3(a->value.x) : vec3_of(*a, "cube size");
                for (int i = 0; i < 3; ++i) positive(a, n.size[i], "cube size");
            }
            if (b.count("center")) n.center = bool_of(*b.at("center"), "center");
        } else if (t.text == "sphere") {
            const auto b = bind(t, args, {"r", "d"});
            n.kind = Kind::sphere;
            if (b.count("r") && b.count("d")) fail(b.at("d")->at, "sphere: give r or d, not both");
            if (b.count("r")) n.r = number_of(*b.at("r"), "sphere r");
            if (b.count("d")) n.r = number_of(*b.at("d"), "sphere d") / 2;
            positive(b.count("r") ? b.at("r") : b.count("d") ? b.at("d") : nullptr, n.r, "sphere radius");
        } else {
            const auto b = bind(t, args, {"h", "r1", "r2", "center", "r", "d", "d1", "d2"});
            n.kind = Kind::cylinder;
            if (b.count("h")) n.h = number_of(*b.at("h"), "cylinder h");
            positive(b.count("h") ? b.at("h") : nullptr, n.h, "cylinder h");
            const int given = int(b.count("r")) + int(b.count("d"));
            if (given > 1) fail(b.at("d")->at, "cylinder: give r or d, not both");
            double r = 1;
            if (b.count("r")) r = number_of(*b.at("r"), "cylinder r");
            if (b.count("d")) r = number_of(*b.at("d"), "cylinder d") / 2;
            n.r1 = n.r2 = r;
            if (b.count("r1") && b.count("d1")) fail(b.at("d1")->at, "cylinder: give r1 or d1, not both");
            if (b.count("r2") && b.count("d2")) fail(b.at("d2")->at, "cylinder: give r2 or d2, not both");
            if (b.count("r1")) n.r1 = number_of(*b.at("r1"), "cylinder r1");
            if (b.count("d1")) n.r1 = number_of(*b.at("d1"), "cylinder d1") / 2;
            if (b.count("r2")) n.r2 = number_of(*b.at("r2"), "cylinder r2");
            if (b.count("d2")) n.r2 = number_of(*b.at("d2"), "cylinder d2") / 2;
            if (!(n.r1 >= 0 && n.r2 >= 0) || !(n.r1 > 0 || n.r2 > 0))
                fail(t, "cylinder radii must be >= 0 and not both 0 (got r1 = " + std::to_string(n.r1) +
                            ", r2 = " + std::to_string(n.r2) + ")");
            if (b.count("center")) n.center = bool_of(*b.at("center"), "center");
        }
        return add(std::move(n));
    }

    glm::dmat4 transform(const Token& t, const std::vector<Arg>& args) {
        glm::dmat4 T(1.0);
        const std::string& m = t.text;
        if (m == "translate") {
            const auto b = bind(t, args, {"v"});
            if (!b.count("v")) fail(t, "translate needs a vector");
            T[3] = glm::dvec4(vec3_of(*b.at("v"), "translate v", true), 1.0);
        } else if (m == "scale") {
            const auto b = bind(t, args, {"v"});
            if (!b.count("v")) fail(t, "scale needs a number or a vector");
            const Arg* a = b.at("v");
            glm::dvec3 s = a->value.type == Value::number ? glm::dvec3(a->value.x) : vec3_of(*a, "scale v", true);
            if (a->value.type == Value::vector && a->value.items().size() == 2) s.z = 1;
            for (int i = 0; i < 3; ++i)
                if (s[i] == 0) fail(a->at, "scale by 0 flattens the solid (not supported)");
            T[0][0] = s.x;
            T[1][1] = s.y;
            T[2][2] = s.z;
        } else if (m == "mirror") {
            const auto b = bind(t, args, {"v"});
            if (!b.count("v")) fail(t, "mirror needs a normal vector");
            const glm::dvec3 v = vec3_of(*b.at("v"), "mirror v", true);
            const double l2 = glm::dot(v, v);
            if (!(l2 > 0) || !std::isfinite(l2)) fail(b.at("v")->at, "mirror's normal must be non-zero and finite");
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r) T[c][r] = (c == r ? 1.0 : 0.0) - 2 * v[c] * v[r] / l2;
        } else if (m == "rotate") {
            const auto b = bind(t, args, {"a", "v"});
            if (!b.count("a")) fail(t, "rotate needs an angle or a vector of angles");
            const Arg* a = b.at("a");
            const double k = std::numbers::pi / 180;
            if (a->value.type == Value::vector) {
                if (b.count("v")) fail(b.at("v")->at, "rotate([ax, ay, az]) takes no axis v");
                const glm::dvec3 ang = vec3_of(*a, "rotate a", true) * k;
                T = axis_rotation({0, 0, 1}, ang.z) * axis_rotation({0, 1, 0}, ang.y) * axis_rotation({1, 0, 0}, ang.x);
            } else {
                glm::dvec3 axis(0, 0, 1);
                if (b.count("v")) axis = vec3_of(*b.at("v"), "rotate v");
                const double l = glm::length(axis);
                if (!(l > 0) || !std::isfinite(l)) fail(b.count("v") ? b.at("v")->at : t, "rotate's axis must be non-zero");
                T = axis_rotation(axis / l, number_of(*a, "rotate a") * k);
            }
        } else {  // multmatrix
            const auto b = bind(t, args, {"m"});
            if (!b.count("m")) fail(t, "multmatrix needs a matrix");
            const Arg* a = b.at("m");
            const Value& v = a->value;
            if (v.type != Value::vector || (v.items().size() != 3 && v.items().size() != 4))
                fail(a->at, "multmatrix m must be 3 or 4 rows of 4 numbers");
            for (std::size_t r = 0; r < v.items().size(); ++r) {
                const Value& row = v.items()[r];
                if (row.type != Value::vector || row.items().size() != 4)
                    fail(a->at, "multmatrix m must be 3 or 4 rows of 4 numbers");
                for (int c = 0; c < 4; ++c) {
                    if (row.items()[c].type != Value::number) fail(a->at, "multmatrix m must hold numbers");
                    T[c][int(r)] = row.items()[c].x;
                }
            }
            if (T[0][3] != 0 || T[1][3] != 0 || T[2][3] != 0 || T[3][3] != 1)
                fail(a->at, "multmatrix: the last row must be 0 0 0 1 (projective maps are not supported)");
        }
        const double det = glm::determinant(glm::dmat3(T));
        if (!std::isfinite(det) || det == 0) fail(t, m + " gives a singular or non-finite matrix");
        return T;
    }
    static glm::dmat4 axis_rotation(const glm::dvec3& u, double a) {
        const double c = std::cos(a), s = std::sin(a), C = 1 - c;
        glm::dmat4 R(1.0);
        R[0] = {c + u.x * u.x * C, u.y * u.x * C + u.z * s, u.z * u.x * C - u.y * s, 0};
        R[1] = {u.x * u.y * C - u.z * s, c + u.y * u.y * C, u.z * u.y * C + u.x * s, 0};
        R[2] = {u.x * u.z * C + u.y * s, u.y * u.z * C - u.x * s, c + u.z * u.z * C, 0};
        return R;
    }
};

}  // namespace

Scene parse(std::string_view text, const std::string& name) { return Parser(text, name).run(); }

Scene read(const std::string& path) {
    // lib's read_text_file: a FIFO, a device (/dev/zero) or a directory is refused, the size is capped
    return parse(read_text_file(path), path);
}

}  // namespace geolab::scad
