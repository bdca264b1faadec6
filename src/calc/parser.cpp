// Lexer and recursive-descent parser for .cal text. Grammar and precedence follow
// RADIANCE calexpr.c as documented in calc(1):
//   E1 -> E1 (+|-) E2 | E2          E2 -> E2 (*|/) E3 | E3
//   E3 -> E4 ^ E3 | E4  (right-associative)
//   E4 -> -E5 | +E5 | E5            E5 -> (E1) | number | name | name(E1, ...) | $N
// `$N` is channel N: an input column in expressions, an output column when defined
// (`$2 = $1*2;`, rcalc).
// RADIANCE compat: unary minus binds tighter than '^', so -2^2 is 4 and 2^-2 is 0.25;
// "--x" is a syntax error. Comments are { ... } and nest.
#include "calc/parser.h"

#include <cctype>
#include <cstdlib>

#include "calc/names.h"

namespace rp::calc {
namespace {

constexpr int kMaxNesting = 400;  // keeps recursive descent far from the stack limit

enum class Tok { End, Number, Name, Punct };

struct Token {
    Tok kind = Tok::End;
    char punct = 0;
    double number = 0;
    std::string text;
    int line = 0;
};

bool isNameStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == kContextMark;
}
bool isNameChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == kContextMark;
}

class Parser {
public:
    Parser(std::string_view text, std::string file, int firstLine)
        : text_(text), file_(std::move(file)), line_(firstLine) {
        advance();
    }

    std::vector<std::shared_ptr<const Definition>> definitions(const std::string& context) {
        std::vector<std::shared_ptr<const Definition>> defs;
        while (tok_.kind != Tok::End) {
            if (isPunct(';')) {  // empty statement
                advance();
                continue;
            }
            defs.push_back(definition(context));
        }
        return defs;
    }

    std::unique_ptr<Expr> wholeExpression() {
        auto e = e1();
        if (tok_.kind != Tok::End) fail("unexpected " + describe(tok_) + " after expression");
        return e;
    }

    [[noreturn]] void fail(const std::string& msg) { fail(tok_.line, msg); }
    [[noreturn]] void fail(int line, const std::string& msg) {
        throw InputError(SourceLoc{file_, line}, "syntax error: " + msg);
    }

private:
    std::shared_ptr<const Definition> definition(const std::string& context) {
        auto def = std::make_shared<Definition>();
        def->loc = SourceLoc{file_, tok_.line};
        def->context = context;
        if (tok_.kind != Tok::Name) fail("expected a name to define, found " + describe(tok_));
        std::string name = tok_.text;
        advance();
        if (isChannelName(name) && isPunct('(')) fail("channel '" + name + "' takes no arguments");
        if (isPunct('(')) {
            def->isFunction = true;
            do {
                advance();
                if (tok_.kind != Tok::Name || isChannelName(tok_.text))
                    fail("expected a parameter name");
                def->params.push_back(tok_.text);
                advance();
            } while (isPunct(','));
            expect(')');
        }
        if (!isPunct('=') && !isPunct(':')) fail("'=' or ':' expected after '" + name + "'");
        def->constant = tok_.punct == ':';
        advance();
        params_ = def->isFunction ? &def->params : nullptr;
        def->paramCalled.assign(def->params.size(), false);
        called_ = &def->paramCalled;
        def->body = e1();
        params_ = nullptr;
        if (tok_.kind != Tok::End) expect(';');
        if (isChannelName(name)) {  // channels are global
            def->name = name;
            return def;
        }
        auto q = qualifiedName(name, context, 0);
        if (!q || q->empty()) fail(def->loc.line, "bad name '" + name + "'");
        def->name = *q;
        return def;
    }

    std::unique_ptr<Expr> node(Expr::Kind k, int line) {
        auto e = std::make_unique<Expr>();
        e->kind = k;
        e->line = line;
        return e;
    }
    std::unique_ptr<Expr> binary(Expr::Kind k, std::unique_ptr<Expr> a, std::unique_ptr<Expr> b) {
        auto e = node(k, a->line);
        e->kids.push_back(std::move(a));
        e->kids.push_back(std::move(b));
        return e;
    }

    std::unique_ptr<Expr> e1() {
        if (++depth_ > kMaxNesting) fail("expression nested too deeply");
        auto a = e2();
        while (isPunct('+') || isPunct('-')) {
            auto k = tok_.punct == '+' ? Expr::Kind::Add : Expr::Kind::Sub;
            advance();
            a = binary(k, std::move(a), e2());
        }
        --depth_;
        return a;
    }
    std::unique_ptr<Expr> e2() {
        auto a = e3();
        while (isPunct('*') || isPunct('/')) {
            auto k = tok_.punct == '*' ? Expr::Kind::Mul : Expr::Kind::Div;
            advance();
            a = binary(k, std::move(a), e3());
        }
        return a;
    }
    std::unique_ptr<Expr> e3() {
        auto a = e4();
        if (!isPunct('^')) return a;
        advance();
        if (++depth_ > kMaxNesting) fail("expression nested too deeply");
        auto b = e3();
        --depth_;
        return binary(Expr::Kind::Pow, std::move(a), std::move(b));
    }
    std::unique_ptr<Expr> e4() {
        if (isPunct('-')) {
            int line = tok_.line;
            advance();
            auto a = e5();
            if (a->kind == Expr::Kind::Number) {  // RADIANCE folds -NUM into the number
                a->number = -a->number;
                return a;
            }
            auto e = node(Expr::Kind::Neg, line);
            e->kids.push_back(std::move(a));
            return e;
        }
        if (isPunct('+')) advance();
        return e5();
    }
    std::unique_ptr<Expr> e5() {
        int line = tok_.line;
        if (isPunct('(')) {
            advance();
            auto e = e1();
            expect(')');
            return e;
        }
        if (tok_.kind == Tok::Number) {
            auto e = node(Expr::Kind::Number, line);
            e->number = tok_.number;
            advance();
            return e;
        }
        if (tok_.kind == Tok::Name) {
            auto e = node(Expr::Kind::Name, line);
            e->name = tok_.text;
            advance();
            if (!isPunct('(') || isChannelName(e->name)) return e;
            e->kind = Expr::Kind::Call;
            if (params_) {  // note parameters used as functions: dot(v1,v2) : v1(1)*...
                for (std::size_t i = 0; i < params_->size(); ++i)
                    if ((*params_)[i] == e->name) (*called_)[i] = true;
            }
            do {
                advance();
                e->kids.push_back(e1());
            } while (isPunct(','));
            expect(')');
            return e;
        }
        fail("unexpected " + describe(tok_));
    }

    bool isPunct(char c) const { return tok_.kind == Tok::Punct && tok_.punct == c; }
    void expect(char c) {
        if (!isPunct(c)) fail(std::string("'") + c + "' expected, found " + describe(tok_));
        advance();
    }
    static std::string describe(const Token& t) {
        switch (t.kind) {
            case Tok::End:
                return "end of input";
            case Tok::Number:
                return "number '" + t.text + "'";
            case Tok::Name:
                return "name '" + t.text + "'";
            case Tok::Punct:
                return std::string("'") + t.punct + "'";
        }
        return "?";
    }

    void skipSpaceAndComments() {
        for (;;) {
            while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
                if (text_[pos_] == '\n') ++line_;
                ++pos_;
            }
            if (pos_ >= text_.size() || text_[pos_] != '{') return;
            int open = line_, nest = 0;
            do {  // comments nest: { a { b } c }
                if (pos_ >= text_.size()) fail(open, "'}' expected to close comment");
                char c = text_[pos_++];
                if (c == '{')
                    ++nest;
                else if (c == '}')
                    --nest;
                else if (c == '\n')
                    ++line_;
            } while (nest > 0);
        }
    }

    void advance() {
        skipSpaceAndComments();
        tok_ = Token{};
        tok_.line = line_;
        if (pos_ >= text_.size()) return;
        char c = text_[pos_];
        std::size_t start = pos_;
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
            while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_])))
                ++pos_;
            if (pos_ < text_.size() && text_[pos_] == '.') {
                ++pos_;
                while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_])))
                    ++pos_;
            }
            if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
                std::size_t save = pos_++;
                if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
                if (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
                    while (pos_ < text_.size() &&
                           std::isdigit(static_cast<unsigned char>(text_[pos_])))
                        ++pos_;
                } else {
                    pos_ = save;  // "2e" or "2ex": the 'e' starts something else
                }
            }
            tok_.kind = Tok::Number;
            tok_.text = std::string(text_.substr(start, pos_ - start));
            if (tok_.text == ".") fail("unexpected '.'");
            tok_.number = std::strtod(tok_.text.c_str(), nullptr);
            return;
        }
        if (c == '$') {  // channel: '$' and its number, as one name
            ++pos_;
            while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_])))
                ++pos_;
            if (pos_ == start + 1) fail("channel number expected after '$'");
            tok_.kind = Tok::Name;
            tok_.text = std::string(text_.substr(start, pos_ - start));
            return;
        }
        if (isNameStart(c)) {
            while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
            tok_.kind = Tok::Name;
            tok_.text = std::string(text_.substr(start, pos_ - start));
            return;
        }
        static constexpr std::string_view kPunct = "(),;=:+-*/^";
        if (kPunct.find(c) != std::string_view::npos) {
            tok_.kind = Tok::Punct;
            tok_.punct = c;
            ++pos_;
            return;
        }
        if (c == '}') fail("'}' without an opening '{'");
        fail(std::string("unexpected character '") + c + "'");
    }

    std::string_view text_;
    std::string file_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int depth_ = 0;
    Token tok_;
    const std::vector<std::string>* params_ = nullptr;
    std::vector<bool>* called_ = nullptr;
};

}  // namespace

std::vector<std::shared_ptr<const Definition>> parseDefinitions(std::string_view text,
                                                                const std::string& file,
                                                                const std::string& context,
                                                                int firstLine) {
    Parser p(text, file, firstLine);
    return p.definitions(contextString(context));
}

std::unique_ptr<Expr> parseExpression(std::string_view text, const SourceLoc& loc) {
    Parser p(text, loc.file, loc.line > 0 ? loc.line : 1);
    return p.wholeExpression();
}

}  // namespace rp::calc
