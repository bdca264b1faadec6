// Code generation: turns the linker's node trees (ir.h) into VM blocks (vm.h). Temporaries
// are allocated like a stack; constants, ray variables and cached variables are read
// straight from globals; x*y + z becomes one instruction; if and select become jumps, so
// their branches stay lazy. Internal to the calc module.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "calc/ir.h"
#include "calc/vm.h"

namespace rp::calc {

class CodeGen {
public:
    explicit CodeGen(CodeImage& image) : img_(image) {}

    // Emits one block computing `body`; a variable's block (`varSlot` >= 0) also caches
    // the value. Returns the block's index.
    int emitBlock(const Node* body, int varSlot = -1);

private:
    int gen(const Node* n, int dst);
    int place(int operand, int dst);
    int target(int dst) { return dst >= 0 ? dst : alloc(); }
    int alloc();
    int constant(double v);
    int emit(Code op, int d = 0, int a = 0, int b = 0, int c = 0, const void* p = nullptr);
    int here() const { return static_cast<int>(img_.code.size()); }
    int args(const Node* n);  // evaluates a call's arguments into consecutive registers
    int binary(Code op, const Node* x, const Node* y, int dst);
    int mulAdd(const Node* n, int dst);
    void forgetVarsAfter(std::size_t n);
    int var(const Node* n, int dst);
    bool inlinable(const VarInfo& v);
    bool reaches(const Node* n, int slot, std::vector<char>& seen) const;

    CodeImage& img_;
    std::map<std::uint64_t, int> constIndex_;
    int top_ = 0, maxTop_ = 0;
    bool argGlobals_ = false;    // generating the version that reads arguments from globals
    int maxArg_ = 0;             // highest argument it read so far
    std::vector<char> ensured_;  // per variable: NeedVar already done on this path
    std::vector<int> ensuredList_;
    // Variable bodies are expanded where first needed (guarded by their cache stamp)
    // unless they are part of a cycle or the block grew too large.
    static constexpr int kMaxInlineCode = 1024;
    int blockStart_ = 0;
    std::vector<signed char> cyclic_;  // per variable: -1 unknown, 0 no, 1 yes
};

}  // namespace rp::calc
