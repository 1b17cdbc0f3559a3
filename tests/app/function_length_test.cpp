// The command line stays a thin client (issue 39): no function in apps/ longer than 60 lines.
// A small scanner finds the function bodies: comments, literals and preprocessor lines are blanked
// first, so that their braces do not count; lambdas, nested blocks and brace initializers inside a
// body belong to that body; namespaces, classes and `extern "C"` blocks are walked into, so
// member functions count; tables (`= {...}`) are not functions. Known blind spot: a constructor
// whose member initializer list uses braces (`m_x{x}`) is not measured.

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

/// The longest function body apps/ may have, in lines between its braces.
constexpr int k_max_body_lines = 60;

/// Files of apps/hikari/ that another change owns; their long functions are that change's to split.
const std::set<std::string> k_not_scanned = {
    "gallery.cpp",  // being rewritten for its figures; plan() is longer than 60 lines
};

/// `text` with comments, string and character literals (raw strings included) and preprocessor
/// lines replaced by spaces; newlines are kept, so positions keep their line numbers.
std::string code_only(std::string_view text) {
    std::string out(text);
    auto blank = [&](size_t from, size_t to) {
        for (size_t i = from; i < to && i < out.size(); ++i)
            if (out[i] != '\n') out[i] = ' ';
    };
    size_t i = 0;
    bool line_start = true;
    while (i < text.size()) {
        const char c = text[i];
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        if (line_start && c == '#') {  // a preprocessor line, with its continuations
            size_t end = i;
            while (end < text.size() && (text[end] != '\n' || text[end - 1] == '\\')) ++end;
            blank(i, end);
            i = end;
        } else if (c == '/' && next == '/') {
            const size_t end = std::min(text.find('\n', i), text.size());
            blank(i, end);
            i = end;
        } else if (c == '/' && next == '*') {
            const size_t end = std::min(text.find("*/", i + 2), text.size() - 2) + 2;
            blank(i, end);
            i = end;
        } else if (c == 'R' && next == '"' && (i == 0 || !std::isalnum(text[i - 1]))) {
            const size_t open = text.find('(', i);
            const std::string close = ")" + std::string(text.substr(i + 2, open - i - 2)) + "\"";
            const size_t end = std::min(text.find(close, open), text.size()) + close.size();
            blank(i, end);
            i = end;
        } else if (c == '"' || (c == '\'' && (i == 0 || !std::isalnum(text[i - 1])))) {
            size_t end = i + 1;
            while (end < text.size() && text[end] != c) end += text[end] == '\\' ? 2 : 1;
            blank(i, end + 1);
            i = end + 1;
        } else {
            ++i;
        }
        if (i > 0 && i <= text.size()) line_start = text[i - 1] == '\n';
        while (line_start && i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    }
    return out;
}

/// Whether `header` (the code between the last `;`, `{` or `}` and a `{`) opens a scope that
/// holds declarations: a namespace, a class, struct, union or enum, or an `extern` block.
bool opens_scope(const std::string& header) {
    static const std::regex scope(R"(\b(namespace|class|struct|union|enum|extern)\b)");
    return header.find('(') == std::string::npos && std::regex_search(header, scope);
}

/// Whether `header` declares a function whose body follows: parentheses, and no `=` outside
/// them (which would make the braces an initializer), unless it is a lambda's (`= [...](...)`).
bool opens_function(const std::string& header) {
    if (header.find('(') == std::string::npos) return false;
    static const std::regex lambda(R"(=\s*\[[^\]]*\]\s*\()");
    if (std::regex_search(header, lambda)) return true;
    int depth = 0;
    for (size_t i = 0; i < header.size(); ++i) {
        const char c = header[i];
        depth += c == '(' || c == '[' || c == '<' ? 1 : c == ')' || c == ']' || c == '>' ? -1 : 0;
        const bool assignment = c == '=' && (i == 0 || !std::strchr("=!<>", header[i - 1])) &&
                                (i + 1 == header.size() || header[i + 1] != '=');
        if (assignment && depth <= 0) return false;
    }
    return true;
}

/// The name a function header declares: the identifier before its first `(`, or for a lambda
/// the variable it initializes.
std::string function_name(const std::string& header) {
    static const std::regex lambda(R"(([A-Za-z_][A-Za-z_0-9]*)\s*=\s*\[)");
    static const std::regex name(R"(([A-Za-z_][A-Za-z_0-9:~]*)\s*\()");
    std::smatch m;
    if (std::regex_search(header, m, lambda)) return m[1].str();
    return std::regex_search(header, m, name) ? m[1].str() : "?";
}

/// A function body found by function_bodies.
struct Body {
    std::string name;
    int line = 0;   ///< 1-based line of its opening brace
    int lines = 0;  ///< lines strictly between its braces
};

/// Every function body of C++ source `text`, in order.
std::vector<Body> function_bodies(std::string_view text) {
    const std::string code = code_only(text);
    std::vector<Body> bodies;
    int line = 1, paren = 0;
    size_t header_start = 0;
    // Open blocks: 's' a scope, 'f' a function body being measured, 'o' any other block.
    std::string open;
    for (size_t i = 0; i < code.size(); ++i) {
        const char c = code[i];
        line += c == '\n';
        const bool at_scope = open.empty() || open.back() == 's';
        if (!at_scope) {
            if (c == '{') open += 'o';
            if (c == '}' && open.back() == 'f') bodies.back().lines = line - bodies.back().line - 1;
            if (c == '}') open.pop_back();
            if (open.empty() || open.back() == 's') header_start = i + 1;
            continue;
        }
        paren += c == '(' ? 1 : c == ')' ? -1 : 0;
        if (paren > 0 || (c != '{' && c != '}' && c != ';')) continue;
        const std::string header = code.substr(header_start, i - header_start);
        header_start = i + 1;
        if (c == '}' && !open.empty()) open.pop_back();
        if (c != '{') continue;
        if (opens_function(header)) {
            open += 'f';
            bodies.push_back({function_name(header), line, 0});
        } else {
            open += opens_scope(header) ? 's' : 'o';
        }
    }
    for (Body& b : bodies) b.lines = std::max(b.lines, 0);
    return bodies;
}

/// A function called `name` whose body is `lines` lines of `statement`.
std::string function_of(const std::string& name, int lines, const std::string& statement) {
    std::string text = "int " + name + "(int x) {\n";
    for (int i = 0; i < lines; ++i) text += "    " + statement + "\n";
    return text + "}\n";
}

/// Each function of `text` by name, with its length in lines.
std::map<std::string, int> lengths(std::string_view text) {
    std::map<std::string, int> out;
    for (const Body& b : function_bodies(text)) out[b.name] = b.lines;
    return out;
}

TEST(FunctionLength, MeasuresLinesBetweenTheBraces) {
    const std::vector<Body> bodies =
        function_bodies(function_of("short_one", 60, "++x;") + function_of("long_one", 61, "++x;"));
    ASSERT_EQ(bodies.size(), 2u);
    EXPECT_EQ(bodies[0].name, "short_one");
    EXPECT_EQ(bodies[0].lines, 60);
    EXPECT_EQ(bodies[1].name, "long_one");
    EXPECT_EQ(bodies[1].lines, 61);
    EXPECT_EQ(bodies[1].line, 63);
}

TEST(FunctionLength, LambdasLiteralsAndCommentsBelongToTheirFunction) {
    const std::string text =
        "namespace a { namespace {\n" +
        function_of("with_lambdas", 3, "auto f = [&](int y) { if (y) { return y; } return 0; };") +
        "void g(std::string s = {}) {\n"
        "    const char* t = \"}{\"; char u = '{';  // }\n"
        "    const char* v = R\"x(}})x\"; /* { */\n"
        "#define BRACE {\n"
        "    call([] { return 1; }, {1, 2});\n"
        "}\n"
        "}}\n";
    EXPECT_EQ(lengths(text), (std::map<std::string, int>{{"with_lambdas", 3}, {"g", 4}}));
}

TEST(FunctionLength, MemberFunctionsCountAndTablesDoNot) {
    const std::string text =
        "constexpr Choice<int> k_table[] = {\n  {\"a\", f(1)},\n  {\"b\", f(2)},\n};\n"
        "struct S : Base {\n  int m() const {\n    return 1;\n  }\n  int n = 0;\n};\n"
        "const auto lambda = [](int x) {\n  return x;\n};\n"
        "extern \"C\" void handler(int) {\n  stop();\n}\n";
    EXPECT_EQ(lengths(text), (std::map<std::string, int>{{"m", 1}, {"lambda", 1}, {"handler", 1}}));
}

TEST(FunctionLength, NoFunctionInAppsIsLongerThanSixtyLines) {
    const fs::path apps = fs::path(HIKARI_SOURCE_DIR) / "apps";
    int files = 0, functions = 0;
    for (const auto& entry : fs::recursive_directory_iterator(apps)) {
        const fs::path& path = entry.path();
        if (!entry.is_regular_file() || k_not_scanned.count(path.filename().string())) continue;
        if (path.extension() != ".cpp" && path.extension() != ".h") continue;
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        for (const Body& b : function_bodies(text.str())) {
            EXPECT_LE(b.lines, k_max_body_lines)
                << path.string() << ":" << b.line << ": " << b.name << " is " << b.lines
                << " lines long; split it into named steps";
            ++functions;
        }
        ++files;
    }
    EXPECT_GT(files, 10);
    EXPECT_GT(functions, 80);
}

}  // namespace
