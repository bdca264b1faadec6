// Builder (loading .cal text), Program lookups and the per-thread Evaluator. The
// compiler itself is in compile.cpp.
#include "calc/program.h"

#include <fstream>
#include <set>
#include <sstream>

#include "calc/builtins.h"
#include "calc/names.h"
#include "calc/parser.h"
#include "calc/ray_context.h"
#include "calc/search_path.h"

namespace rp::calc {

Builder::Builder(std::vector<std::string> searchPath) : searchPath_(std::move(searchPath)) {}

void Builder::setContext(std::string_view context) { context_ = contextString(context); }

void Builder::loadFile(const std::string& name) {
    auto path = findFile(name, searchPath_);
    if (!path) {
        std::string dirs;
        for (const auto& d : searchPath_) dirs += (dirs.empty() ? "" : ":") + d;
        throw InputError(SourceLoc{name, 0}, "cannot find function file (searched " +
                                                 (dirs.empty() ? std::string("nothing") : dirs) +
                                                 ")");
    }
    std::ifstream in(*path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    if (!in && !in.eof()) throw InputError(SourceLoc{*path, 0}, "cannot read function file");
    loadString(ss.str(), *path);
}

void Builder::loadString(std::string_view text, const std::string& source, int firstLine) {
    auto defs = parseDefinitions(text, source, context_, firstLine);
    defs_.insert(defs_.end(), defs.begin(), defs.end());
}

int Builder::addExpression(std::string_view text, const SourceLoc& loc) {
    exprs_.push_back(PendingExpr{parseExpression(text, loc), context_, loc});
    return static_cast<int>(exprs_.size()) - 1;
}

void Builder::addExternal(const std::string& name) { externals_.push_back(name); }

std::optional<Entry> Program::variable(std::string_view name, std::string_view context) const {
    std::string ctx = contextString(context);
    for (int level = 0;; ++level) {
        auto q = qualifiedName(name, ctx, level);
        if (!q) break;
        if (auto it = varIndex_.find(*q); it != varIndex_.end()) {
            const VarInfo& v = *vars_[it->second];
            if (v.body && v.body->fn == &evConst) return Entry{v.body};  // no cache slot
            return Entry{varEntries_[it->second], image_.varBlock[v.slot], v.slot};
        }
    }
    return std::nullopt;
}

std::optional<Function> Program::function(std::string_view name, std::string_view context) const {
    std::string ctx = contextString(context);
    for (int level = 0;; ++level) {
        auto q = qualifiedName(name, ctx, level);
        if (!q) break;
        if (auto it = functionIndex_.find(*q); it != functionIndex_.end())
            return Function{static_cast<double>(it->second), functions_[it->second]->nparams};
    }
    auto bs = builtins();
    for (std::size_t i = 0; i < bs.size(); ++i)
        if (bs[i].name == name)
            return Function{builtinFunctionId(static_cast<int>(i)), bs[i].minArgs};
    return std::nullopt;
}

bool Program::readsOnly(int id, std::span<const std::string_view> allowed) const {
    return nodeReadsOnly(expressions_.at(id), allowed);
}

bool Program::readsOnly(const Function& f, std::span<const std::string_view> allowed) const {
    if (f.id < 0) return true;  // builtins take everything as arguments
    const FunctionInfo* fi = functions_.at(static_cast<std::size_t>(f.id)).get();
    return fi->body && nodeReadsOnly(fi->body, allowed);
}

bool Program::nodeReadsOnly(const Node* root, std::span<const std::string_view> allowed) const {
    std::set<std::size_t> ok;
    for (const RayVariable& v : rayVariables())
        for (std::string_view a : allowed)
            if (v.name == a) ok.insert(v.offset);
    std::set<const void*> seen;  // variables and functions already walked
    std::vector<const Node*> todo{root};
    while (!todo.empty()) {
        const Node* n = todo.back();
        todo.pop_back();
        if (!n) return false;
        switch (n->op()) {
            case Op::Ray:
                if (!ok.count(static_cast<std::size_t>(n->index))) return false;
                break;
            case Op::Var: {
                const auto* v = static_cast<const VarInfo*>(n->ptr);
                if (!v || !v->body) return false;
                if (seen.insert(v).second) todo.push_back(v->body);
                break;
            }
            case Op::CallUser: {
                const auto* f = static_cast<const FunctionInfo*>(n->ptr);
                if (!f || !f->body) return false;
                if (seen.insert(f).second) todo.push_back(f->body);
                break;
            }
            case Op::CallParamFn:
            case Op::Error:
                return false;
            default:
                break;
        }
        for (const Node* k : {n->a, n->b, n->c})
            if (k) todo.push_back(k);
        for (int i = 0; i < n->nkids; ++i) todo.push_back(n->kids[i]);
    }
    return true;
}

Evaluator::Evaluator(std::shared_ptr<const Program> program) : program_(std::move(program)) {
    RP_CHECK(program_ != nullptr);
    machine_.attach(program_->image_);
}

void Evaluator::setRay(const RayContext& ray) { machine_.setRay(ray); }

double Evaluator::eval(Entry e) {
    RP_CHECK(e.node != nullptr);
    if (e.block < 0) return e.node->num;
    double v;
    if (e.slot >= 0 && machine_.cached(e.slot, v)) return v;
    return machine_.run(e.block);
}

void Evaluator::set(Entry e, double value) {
    RP_CHECK(e.slot >= 0);
    machine_.setCached(e.slot, value);
}

double Evaluator::call(const Function& f, std::span<const double> args) {
    return machine_.call(f.id, args.data(), static_cast<int>(args.size()));
}

}  // namespace rp::calc
