// Inlining rules (see inlining.h).
#include "calc/inlining.h"

#include <vector>

namespace rp::calc {
namespace {

constexpr int kInlineMaxNodes = 48;

bool isCheapArg(const Node* n) {
    return n->fn == &evConst || n->fn == &evRay || n->fn == &evModArg || n->fn == &evParam ||
           n->fn == &evVar;
}

// Counts nodes and parameter uses; false if the body cannot be inlined.
bool scanBody(const Node* n, std::vector<int>& uses, int& count) {
    if (++count > kInlineMaxNodes) return false;
    if (n->fn == &evParamDyn || n->fn == &evCallParamFn || n->fn == &evError) return false;
    if (n->fn == &evParam) {
        if (n->index < 1 || n->index > static_cast<int>(uses.size())) return false;
        ++uses[n->index - 1];
        return true;
    }
    for (const Node* k : {n->a, n->b, n->c})
        if (k && !scanBody(k, uses, count)) return false;
    for (int i = 0; i < n->nkids; ++i)
        if (n->kids[i] != n->a && !scanBody(n->kids[i], uses, count)) return false;
    return true;
}

}  // namespace

bool canInline(const FunctionInfo& f, const Node* call) {
    std::vector<int> uses(call->nkids, 0);
    int count = 0;
    if (!f.body || !scanBody(f.body, uses, count)) return false;
    for (int i = 0; i < call->nkids; ++i)
        if (uses[i] > 1 && !isCheapArg(call->kids[i])) return false;
    return true;
}

}  // namespace rp::calc
