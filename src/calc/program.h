// Public interface of the .cal language: a Builder collects definitions from files
// (found along RAYPATH) and inline text, build() compiles them once into an immutable,
// shareable Program, and each thread evaluates it through its own small Evaluator.
//
//   calc::Builder b(calc::defaultSearchPath(libDir));
//   b.loadFile("rayinit.cal");
//   b.loadFile("skybright.cal");
//   auto prog = b.build();
//   auto skybr = prog->variable("skybr");          // resolved once
//   calc::Evaluator ev(prog);                       // one per thread
//   ev.setRay(ray);                                 // per ray: clears cached variables
//   double v = ev.eval(*skybr);
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "calc/ast.h"
#include "calc/ir.h"
#include "calc/ray_context.h"
#include "calc/vm.h"

namespace rp::calc {

class Program;

// Something to evaluate: a variable (cached per ray) or a compiled expression.
struct Entry {
    const Node* node = nullptr;
    int block = -1;  // its code (none for constants)
    int slot = -1;   // cache slot of a variable
};

// An output channel `$N = expr;` (rcalc's output columns).
struct OutputChannel {
    int channel = 0;
    Entry entry;
};

// A function to call with arguments: user-defined (index >= 0) or builtin.
struct Function {
    double id = 0;    // see builtinFunctionId
    int nparams = 0;  // declared parameters (builtins: minimum)
};

class Builder {
public:
    // `searchPath`: directories for loadFile (see search_path.h).
    explicit Builder(std::vector<std::string> searchPath = {});

    // Context for subsequent loads (names.h): "" is global, "sky" becomes "`sky".
    void setContext(std::string_view context);
    const std::string& context() const { return context_; }

    // Loads a .cal file found along the search path. Later definitions of a name
    // replace earlier ones. Throws InputError (missing file, syntax error with file:line).
    void loadFile(const std::string& name);
    // Loads inline definitions (rtrace -e). `source` names them in errors ("" = command
    // line).
    void loadString(std::string_view text, const std::string& source = "", int firstLine = 1);
    // Registers a bare expression (a modifier's coordinate argument) to be compiled in
    // the current context; returns its id for Program::expression().
    int addExpression(std::string_view text, const SourceLoc& loc);
    // A variable whose value the program sets per evaluation (Evaluator::set), replacing
    // any definition of `name`, earlier or later (rcalc's recno, outno and input-format
    // fields, which RADIANCE sets with varset). Unset, it is an undefined variable.
    void addExternal(const std::string& name);
    // Lets expressions read input channels: `$N` and in(n) (rcalc). Without it, `$N` is
    // an error where it is evaluated and in() is an undefined function.
    void enableChannels() { channels_ = true; }

    // Compiles everything loaded so far. May be called again after loading more.
    std::shared_ptr<const Program> build() const;

    const std::vector<std::string>& searchPath() const { return searchPath_; }

private:
    struct PendingExpr {
        std::shared_ptr<const Expr> expr;
        std::string context;
        SourceLoc loc;
    };
    std::vector<std::string> searchPath_;
    std::string context_;
    std::vector<std::shared_ptr<const Definition>> defs_;
    std::vector<PendingExpr> exprs_;
    std::vector<std::string> externals_;
    bool channels_ = false;
    friend class Linker;
};

// Immutable after build(); safe to share between threads.
class Program {
public:
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    // Looks `name` up as code in `context` would see it (names.h search rules).
    std::optional<Entry> variable(std::string_view name, std::string_view context = "") const;
    std::optional<Function> function(std::string_view name, std::string_view context = "") const;
    Entry expression(int id) const { return Entry{expressions_.at(id), expressionBlocks_.at(id)}; }

    // Whether expression `id` (with everything it calls and reads, transitively) reads no
    // ray variables but those named in `allowed`. False where that cannot be known (a
    // function passed as a parameter, an unresolved name).
    bool readsOnly(int id, std::span<const std::string_view> allowed) const;
    // The same for a function (builtins read none).
    bool readsOnly(const Function& f, std::span<const std::string_view> allowed) const;

    // References that could not be resolved and other problems found while compiling,
    // as "file:line: message". Each is also raised as an InputError if evaluated.
    const std::vector<std::string>& problems() const { return problems_; }

    // The output channels defined, in channel order (a later `$N` replaces an earlier one).
    const std::vector<OutputChannel>& outputChannels() const { return outputs_; }

    int variableSlots() const { return static_cast<int>(vars_.size()); }

private:
    Program() = default;
    bool nodeReadsOnly(const Node* root, std::span<const std::string_view> allowed) const;
    friend class Linker;
    friend class Evaluator;

    std::deque<Node> nodes_;
    std::deque<std::vector<const Node*>> kidLists_;
    std::deque<NodeInfo> infos_;
    std::vector<std::unique_ptr<VarInfo>> vars_;
    std::vector<const Node*> varEntries_;  // evVar node per variable
    std::vector<std::unique_ptr<FunctionInfo>> functions_;
    std::vector<const FunctionInfo*> functionTable_;
    std::map<std::string, int, std::less<>> varIndex_;
    std::map<std::string, int, std::less<>> functionIndex_;
    std::vector<const Node*> expressions_;
    std::vector<int> expressionBlocks_;
    CodeImage image_;
    std::vector<std::string> problems_;
    std::vector<OutputChannel> outputs_;
};

// Per-thread evaluation state: the variable cache and the call stack. Cheap to create;
// not thread-safe itself, one per thread.
class Evaluator {
public:
    explicit Evaluator(std::shared_ptr<const Program> program);

    // Starts a new evaluation for `ray` (kept by reference until the next setRay):
    // variables cached for the previous ray are forgotten.
    void setRay(const RayContext& ray);

    double eval(Entry e);
    // Gives the variable of `e` (an external one) `value` until the next setRay.
    void set(Entry e, double value);
    // Where `$N` and in(n) read (kept by pointer; null: none).
    void setChannels(ChannelSource* channels) { machine_.setChannels(channels); }
    double call(const Function& f, std::span<const double> args);

    // Divisions by zero and library calls with non-finite results so far (each gave 0).
    long mathErrors() const { return machine_.mathErrors; }

private:
    std::shared_ptr<const Program> program_;
    Machine machine_;
};

}  // namespace rp::calc
