// The linker: turns the Builder's definitions into a Program. Resolves every name once
// (context search, then ray variables and builtins), folds constant subexpressions and
// constant-function calls, and turns what cannot be resolved into error nodes that raise
// an InputError with the reference's file:line when (and only when) evaluated, as
// RADIANCE reports undefined names at evaluation time. Folding runs the VM on a scratch
// block; at the end every variable, function and expression gets its code (codegen.h).
#include <cmath>
#include <cstdlib>
#include <deque>

#include "calc/builtins.h"
#include "calc/codegen.h"
#include "calc/inlining.h"
#include "calc/names.h"
#include "calc/program.h"

namespace rp::calc {

class Linker {
public:
    explicit Linker(const Builder& b) : b_(b), p_(new Program()) {}

    std::shared_ptr<const Program> run() {
        collect();
        propagateFunctionParams();
        for (int i = 0; i < static_cast<int>(varDefs_.size()); ++i) compileVar(i);
        for (int i = 0; i < static_cast<int>(funcDefs_.size()); ++i) compileFunction(i);
        for (const auto& e : b_.exprs_) {
            Scope scope{&e.context, nullptr, nullptr, e.loc.file};
            p_->expressions_.push_back(compile(*e.expr, scope));
        }
        std::vector<const Node*> outputs;
        for (const auto& [n, d] : outputDefs_) {
            Scope scope{&d->context, nullptr, nullptr, d->loc.file};
            outputs.push_back(compile(*d->body, scope));
        }
        // Code for everything: every variable, function and expression gets a block.
        CodeImage& img = p_->image_;
        for (const auto& v : p_->vars_) img.varBlock[v->slot] = gen_.emitBlock(v->body, v->slot);
        generateFunctions();
        for (const Node* e : p_->expressions_) p_->expressionBlocks_.push_back(gen_.emitBlock(e));
        std::size_t k = 0;
        for (const auto& [n, d] : outputDefs_) {
            const Node* body = outputs[k++];
            p_->outputs_.push_back(OutputChannel{n, Entry{body, gen_.emitBlock(body)}});
        }
        return std::shared_ptr<const Program>(std::move(p_));
    }

private:
    enum class State { Todo, Busy, Done };
    struct Scope {
        const std::string* context;
        const Definition* fdef;  // function whose body this is, or null
        FunctionInfo* fn;
        std::string file;
        bool pure = true;  // no ray, modifier or non-constant variable dependence
    };
    enum class RefKind { None, Var, Func, Ray, Builtin, If, Select, Arg, Chan, In };
    struct Ref {
        RefKind kind = RefKind::None;
        int index = 0;
    };

    void collect() {
        std::vector<const Definition*> all;
        for (const auto& d : b_.defs_) all.push_back(d.get());
        for (const std::string& name : b_.externals_) {  // externals win over definitions
            auto& d = externalDefs_.emplace_back();
            d.name = name;
            d.external = true;
            d.loc = SourceLoc{"", 0};
            all.push_back(&d);
        }
        std::map<std::string, int> last;  // later definitions win
        for (int i = 0; i < static_cast<int>(all.size()); ++i) last[all[i]->name] = i;
        for (const auto& [name, i] : last) {
            const Definition& d = *all[i];
            if (isChannelName(d.name)) {  // output channel, kept in channel order
                outputDefs_.emplace(std::atoi(d.name.c_str() + 1), &d);
                continue;
            }
            if (d.isFunction) {
                auto f = std::make_unique<FunctionInfo>();
                f->name = d.name;
                f->index = static_cast<int>(funcDefs_.size());
                f->nparams = static_cast<int>(d.params.size());
                f->constant = d.constant;
                f->paramCalled = d.paramCalled;
                f->loc = d.loc;
                p_->functionIndex_[d.name] = static_cast<int>(funcDefs_.size());
                p_->functionTable_.push_back(f.get());
                p_->functions_.push_back(std::move(f));
                funcDefs_.push_back(&d);
            } else {
                auto v = std::make_unique<VarInfo>();
                v->name = d.name;
                v->slot = static_cast<int>(varDefs_.size());
                v->loc = d.loc;
                Node* entry = newNode(evVar);
                entry->index = v->slot;
                entry->ptr = v.get();
                entry->info = newInfo(d.loc, d.name);
                p_->varIndex_[d.name] = v->slot;
                p_->varEntries_.push_back(entry);
                p_->vars_.push_back(std::move(v));
                varDefs_.push_back(&d);
            }
        }
        varState_.assign(varDefs_.size(), State::Todo);
        funcState_.assign(funcDefs_.size(), State::Todo);
        CodeImage& img = p_->image_;
        img.nvars = static_cast<int>(varDefs_.size());
        img.varBlock.assign(varDefs_.size(), -1);
        img.funcBlock.assign(funcDefs_.size(), -1);
        img.functions = p_->functionTable_;
    }

    // A parameter passed on to another function's function-valued parameter is itself
    // function-valued: twice(f, x) = apply(f, apply(f, x)). Iterate to a fixed point.
    void propagateFunctionParams() {
        for (bool changed = true; changed;) {
            changed = false;
            for (std::size_t i = 0; i < funcDefs_.size(); ++i)
                changed |= markPassedParams(*funcDefs_[i]->body, *funcDefs_[i], *p_->functions_[i]);
        }
    }
    bool markPassedParams(const Expr& e, const Definition& d, FunctionInfo& f) {
        bool changed = false;
        for (const auto& k : e.kids) changed |= markPassedParams(*k, d, f);
        if (e.kind != Expr::Kind::Call) return changed;
        for (std::size_t p = 0; p < d.params.size(); ++p)
            if (d.params[p] == e.name) return changed;  // a call through a parameter
        Ref r = resolve(e.name, d.context);
        if (r.kind != RefKind::Func) return changed;
        const auto& callee = p_->functions_[r.index]->paramCalled;
        for (std::size_t j = 0; j < e.kids.size() && j < callee.size(); ++j) {
            if (!callee[j] || e.kids[j]->kind != Expr::Kind::Name) continue;
            for (std::size_t p = 0; p < d.params.size(); ++p) {
                if (d.params[p] == e.kids[j]->name && !f.paramCalled[p]) {
                    f.paramCalled[p] = true;
                    changed = true;
                }
            }
        }
        return changed;
    }

    void compileVar(int i) {
        if (varState_[i] != State::Todo) return;
        varState_[i] = State::Busy;
        const Definition& d = *varDefs_[i];
        Scope scope{&d.context, nullptr, nullptr, d.loc.file};
        // An external variable has no body: it must be given its value (Evaluator::set).
        if (d.external) {  // not a problem of the program's: listed in no problems()
            Node* n = newNode(evError);
            n->info = newInfo(d.loc, "undefined variable '" + d.name + "'");
            p_->vars_[i]->body = n;
        } else {
            p_->vars_[i]->body = compile(*d.body, scope);
        }
        varState_[i] = State::Done;
    }

    void compileFunction(int i) {
        if (funcState_[i] != State::Todo) return;
        funcState_[i] = State::Busy;
        const Definition& d = *funcDefs_[i];
        FunctionInfo& f = *p_->functions_[i];
        Scope scope{&d.context, &d, &f, d.loc.file};
        f.body = compile(*d.body, scope);
        f.pure = scope.pure;
        funcState_[i] = State::Done;
    }

    Ref resolve(const std::string& name, const std::string& context) const {
        for (int level = 0;; ++level) {
            auto q = qualifiedName(name, context, level);
            if (!q) break;
            if (auto it = p_->varIndex_.find(*q); it != p_->varIndex_.end())
                return {RefKind::Var, it->second};
            if (auto it = p_->functionIndex_.find(*q); it != p_->functionIndex_.end())
                return {RefKind::Func, it->second};
        }
        if (name.find(kContextMark) != std::string::npos) return {};
        if (isChannelName(name)) return {RefKind::Chan};
        if (name == "in" && b_.channels_) return {RefKind::In};
        if (name == "if") return {RefKind::If};
        if (name == "select") return {RefKind::Select};
        if (name == "arg") return {RefKind::Arg};
        auto rv = rayVariables();
        for (std::size_t i = 0; i < rv.size(); ++i)
            if (rv[i].name == name) return {RefKind::Ray, static_cast<int>(i)};
        auto bs = builtins();
        for (std::size_t i = 0; i < bs.size(); ++i)
            if (bs[i].name == name) return {RefKind::Builtin, static_cast<int>(i)};
        return {};
    }

    int paramOf(const std::string& name, const Scope& s) const {
        if (!s.fdef) return -1;
        for (std::size_t i = 0; i < s.fdef->params.size(); ++i)
            if (s.fdef->params[i] == name) return static_cast<int>(i);
        return -1;
    }

    Node* newNode(const NodeKind& kind) {
        Node& n = p_->nodes_.emplace_back();
        n.fn = &kind;
        return &n;
    }
    const NodeInfo* newInfo(const SourceLoc& loc, std::string text) {
        return &p_->infos_.emplace_back(NodeInfo{loc, std::move(text)});
    }
    const Node* constant(double v) {
        Node* n = newNode(evConst);
        n->num = v;
        return n;
    }
    static bool isConst(const Node* n) { return n->fn == &evConst; }
    // Context-free leaves that a variable reference may use directly instead of caching.
    static bool isLeaf(const Node* n) {
        return n->fn == &evConst || n->fn == &evRay || n->fn == &evModArg;
    }
    const Node* error(const Scope& s, int line, const std::string& msg) {
        SourceLoc loc{s.file, line};
        p_->problems_.push_back(InputError(loc, msg).what());
        Node* n = newNode(evError);
        n->info = newInfo(loc, msg);
        return n;
    }
    // Functions whose bodies are complete and have no code yet get their blocks.
    void generateFunctions() {
        CodeImage& img = p_->image_;
        for (std::size_t i = 0; i < funcDefs_.size(); ++i)
            if (img.funcBlock[i] < 0 && funcState_[i] == State::Done)
                img.funcBlock[i] = gen_.emitBlock(p_->functions_[i]->body);
    }
    // Evaluates a constant subexpression now with a scratch block that is dropped again.
    const Node* fold(const Node* n) {
        generateFunctions();
        CodeImage& img = p_->image_;
        const std::size_t codeSize = img.code.size(), blockCount = img.blocks.size();
        int block = gen_.emitBlock(n);
        double v;
        try {
            fold_.attach(img);
            v = fold_.run(block);
        } catch (...) {
            img.code.resize(codeSize);
            img.blocks.resize(blockCount);
            throw;
        }
        img.code.resize(codeSize);
        img.blocks.resize(blockCount);
        return constant(v);
    }
    const Node* const* kidList(std::vector<const Node*> kids) {
        return p_->kidLists_.emplace_back(std::move(kids)).data();
    }

    const Node* binary(const NodeKind& fn, const Node* a, const Node* b) {
        Node* n = newNode(fn);
        n->a = a;
        n->b = b;
        if (isConst(a) && isConst(b)) return fold(n);
        return withConstant(n);
    }
    // One constant operand of + - * is kept in the node itself (x + 1.01, 10*exp(..)):
    // one operand fetch less, same arithmetic and result.
    static const Node* withConstant(Node* n) {
        const Node *a = n->a, *b = n->b;
        if (n->fn == &evAdd || n->fn == &evMul) {
            if (isConst(a)) std::swap(a, b);  // + and * commute exactly in IEEE arithmetic
            if (isConst(b)) {
                n->fn = n->fn == &evAdd ? &evAddC : &evMulC;
                n->num = b->num;
                n->a = a;
                n->b = nullptr;
            }
        } else if (n->fn == &evSub) {
            if (isConst(b)) {
                n->fn = &evSubC;
                n->num = b->num;
                n->b = nullptr;
            } else if (isConst(a)) {
                n->fn = &evCSub;
                n->num = a->num;
                n->a = b;
                n->b = nullptr;
            }
        }
        return n;
    }

    const Node* compile(const Expr& e, Scope& s) {
        using K = Expr::Kind;
        switch (e.kind) {
            case K::Number:
                return constant(e.number);
            case K::Neg: {
                const Node* a = compile(*e.kids[0], s);
                if (isConst(a)) return constant(-a->num);
                Node* n = newNode(evNeg);
                n->a = a;
                return n;
            }
            case K::Add:
                return binary(evAdd, compile(*e.kids[0], s), compile(*e.kids[1], s));
            case K::Sub:
                return binary(evSub, compile(*e.kids[0], s), compile(*e.kids[1], s));
            case K::Mul:
                return binary(evMul, compile(*e.kids[0], s), compile(*e.kids[1], s));
            case K::Div:
                return binary(evDiv, compile(*e.kids[0], s), compile(*e.kids[1], s));
            case K::Pow: {
                const Node* a = compile(*e.kids[0], s);
                const Node* b = compile(*e.kids[1], s);
                if (isConst(b) && !isConst(a) && b->num == std::floor(b->num) &&
                    std::fabs(b->num) <= 64) {
                    Node* n = newNode(evPowInt);  // x^10 by squaring, as fast as a multiply
                    n->a = a;
                    n->index = static_cast<int>(b->num);
                    return n;
                }
                return binary(evPow, a, b);
            }
            case K::Name:
                return compileName(e, s);
            case K::Call:
                return compileCall(e, s);
        }
        return error(s, e.line, "internal: unknown expression");
    }

    const Node* compileName(const Expr& e, Scope& s) {
        if (int p = paramOf(e.name, s); p >= 0) {
            Node* n = newNode(evParam);
            n->index = p + 1;
            n->info = newInfo({s.file, e.line}, e.name);
            return n;
        }
        Ref r = resolve(e.name, *s.context);
        switch (r.kind) {
            case RefKind::Var:
                return varRef(r.index, s);
            case RefKind::Ray: {
                s.pure = false;
                Node* n = newNode(evRay);
                n->index = static_cast<int>(rayVariables()[r.index].offset);
                return n;
            }
            case RefKind::None:
                s.pure = false;
                return error(s, e.line, "undefined variable '" + e.name + "'");
            case RefKind::Chan:
                s.pure = false;
                return channel(constant(std::atoi(e.name.c_str() + 1)), 0, e, s);
            default:
                s.pure = false;
                return error(s, e.line, "'" + e.name + "' is a function; it needs arguments");
        }
    }

    const Node* varRef(int i, Scope& s) {
        compileVar(i);
        if (varState_[i] == State::Done) {
            const Node* body = p_->vars_[i]->body;
            if (isConst(body)) return body;
            s.pure = false;
            if (isLeaf(body)) return body;
        }
        s.pure = false;
        return p_->varEntries_[i];
    }

    const Node* inlineCall(const FunctionInfo& f, const Node* call) {
        return cloneWith(f.body, call->kids);
    }
    const Node* cloneWith(const Node* n, const Node* const* args) {
        if (n->fn == &evParam) return args[n->index - 1];
        if (n->fn == &evConst || n->fn == &evRay || n->fn == &evModArg || n->fn == &evVar) return n;
        Node* c = newNode(*n->fn);
        *c = *n;
        if (n->nkids > 0) {
            std::vector<const Node*> kids;
            for (int i = 0; i < n->nkids; ++i) kids.push_back(cloneWith(n->kids[i], args));
            c->kids = kidList(std::move(kids));
            if (n->a == n->kids[0]) c->a = c->kids[0];
        }
        if (n->a && !(n->nkids > 0 && n->a == n->kids[0])) c->a = cloneWith(n->a, args);
        if (n->b) c->b = cloneWith(n->b, args);
        if (n->c) c->c = cloneWith(n->c, args);
        // Fold what became constant.
        if (c->fn == &evIf && isConst(c->a)) return c->a->num > 0 ? c->b : c->c;
        bool foldable = c->fn == &evNeg || c->fn == &evAdd || c->fn == &evSub || c->fn == &evMul ||
                        c->fn == &evDiv || c->fn == &evPow || c->fn == &evPowInt ||
                        c->fn == &evMath1 || c->fn == &evBuiltinN || c->fn == &evAddC ||
                        c->fn == &evSubC || c->fn == &evCSub || c->fn == &evMulC;
        if (foldable) {
            bool allConst = true;
            for (const Node* k : {c->a, c->b})
                if (k && !isConst(k)) allConst = false;
            for (int i = 0; i < c->nkids; ++i)
                if (!isConst(c->kids[i])) allConst = false;
            if (allConst) return fold(c);
        }
        if (c->fn == &evAdd || c->fn == &evSub || c->fn == &evMul) return withConstant(c);
        return c;
    }

    // Input channel `index` ($N: flavour 0, in(n): 1), where the Builder allows channels.
    const Node* channel(const Node* index, int flavour, const Expr& e, Scope& s) {
        if (!b_.channels_)
            return error(s, e.line, "input channel '" + e.name + "' is not available here");
        Node* n = newNode(evChan);
        n->a = index;
        n->index = flavour;
        n->info = newInfo({s.file, e.line}, e.name);
        return n;
    }

    // An argument passed to a parameter that the callee calls: must name a function.
    const Node* functionRef(const Expr& e, Scope& s) {
        if (e.kind == Expr::Kind::Name) {
            if (int p = paramOf(e.name, s); p >= 0) {  // pass our own function parameter on
                Node* n = newNode(evParam);
                n->index = p + 1;
                n->info = newInfo({s.file, e.line}, e.name);
                return n;
            }
            Ref r = resolve(e.name, *s.context);
            if (r.kind == RefKind::Func) return constant(r.index);
            if (r.kind == RefKind::Builtin) return constant(builtinFunctionId(r.index));
        }
        s.pure = false;
        return error(s, e.line, "expected a function name as argument");
    }

    const Node* compileCall(const Expr& e, Scope& s) {
        const int nargs = static_cast<int>(e.kids.size());
        std::vector<const Node*> kids;
        auto args = [&](const std::vector<bool>* fnParams) {
            bool allConst = true;
            for (int i = 0; i < nargs; ++i) {
                bool isFn = fnParams && i < static_cast<int>(fnParams->size()) && (*fnParams)[i];
                kids.push_back(isFn ? functionRef(*e.kids[i], s) : compile(*e.kids[i], s));
                allConst = allConst && isConst(kids.back());
            }
            return allConst;
        };
        const NodeInfo* site = newInfo({s.file, e.line}, e.name);
        if (int p = paramOf(e.name, s); p >= 0) {
            args(nullptr);
            s.pure = false;
            Node* n = newNode(evCallParamFn);
            n->index = p + 1;
            n->nkids = nargs;
            n->kids = kidList(std::move(kids));
            n->info = site;
            return n;
        }
        Ref r = resolve(e.name, *s.context);
        switch (r.kind) {
            case RefKind::Func: {
                compileFunction(r.index);
                FunctionInfo* f = p_->functions_[r.index].get();
                bool allConst = args(&f->paramCalled);
                State st = funcState_[r.index];
                if (st == State::Busy && f != s.fn) s.pure = false;  // mutual recursion
                if (st == State::Done && !f->pure) s.pure = false;
                Node* n = newNode(evCallUser);
                n->ptr = f;
                n->nkids = nargs;
                n->kids = kidList(std::move(kids));
                n->info = site;
                // RADIANCE compat: a ':' function called with constant arguments is folded.
                if (allConst && f->constant && st == State::Done && f->pure) return fold(n);
                if (st == State::Done && f != s.fn && canInline(*f, n)) return inlineCall(*f, n);
                return n;
            }
            case RefKind::If: {
                if (nargs != 3) return error(s, e.line, "if() takes 3 arguments");
                args(nullptr);
                if (isConst(kids[0])) return kids[0]->num > 0 ? kids[1] : kids[2];
                Node* n = newNode(evIf);
                n->a = kids[0];
                n->b = kids[1];
                n->c = kids[2];
                return n;
            }
            case RefKind::Select: {
                if (nargs < 2) return error(s, e.line, "select() needs an index and values");
                args(nullptr);
                if (isConst(kids[0])) {
                    const int k = roundedIndex(kids[0]->num);
                    if (k == 0) return constant(nargs - 1);
                    if (k >= 1 && k < nargs) return kids[k];
                }
                Node* n = newNode(evSelect);
                n->nkids = nargs;
                n->kids = kidList(std::move(kids));
                n->info = site;
                return n;
            }
            case RefKind::Arg: {
                if (nargs != 1) return error(s, e.line, "arg() takes 1 argument");
                args(nullptr);
                Node* n;
                if (s.fdef) {  // arg(n) in a function: its own arguments
                    n = newNode(isConst(kids[0]) ? evParam : evParamDyn);
                } else {  // outside functions: the modifier's real arguments
                    s.pure = false;
                    n = newNode(isConst(kids[0]) ? evModArg : evModArgDyn);
                }
                if (isConst(kids[0])) n->index = roundedIndex(kids[0]->num);
                n->a = kids[0];
                n->info = site;
                return n;
            }
            case RefKind::In: {
                if (nargs != 1) return error(s, e.line, "in() takes 1 argument");
                args(nullptr);
                s.pure = false;
                return channel(kids[0], 1, e, s);
            }
            case RefKind::Builtin: {
                const Builtin& b = builtins()[r.index];
                if (nargs < b.minArgs || nargs > b.maxArgs)
                    return error(s, e.line,
                                 "function '" + e.name + "' takes " + std::to_string(b.minArgs) +
                                     " argument(s), got " + std::to_string(nargs));
                bool allConst = args(nullptr);
                Node* n = newNode(b.f1 ? evMath1 : evBuiltinN);
                n->ptr = &b;
                n->a = kids[0];
                n->nkids = nargs;
                n->kids = kidList(std::move(kids));
                n->info = site;
                return allConst ? fold(n) : n;
            }
            case RefKind::Var:
            case RefKind::Ray:
            case RefKind::Chan:
                s.pure = false;
                return error(s, e.line, "'" + e.name + "' is a variable, not a function");
            case RefKind::None:
                break;
        }
        s.pure = false;
        return error(s, e.line, "undefined function '" + e.name + "'");
    }

    const Builder& b_;
    std::unique_ptr<Program> p_;
    std::vector<const Definition*> varDefs_, funcDefs_;
    std::map<int, const Definition*> outputDefs_;  // output channels by number
    std::deque<Definition> externalDefs_;
    std::vector<State> varState_, funcState_;
    CodeGen gen_{p_->image_};
    Machine fold_;
};

std::shared_ptr<const Program> Builder::build() const { return Linker(*this).run(); }

}  // namespace rp::calc
