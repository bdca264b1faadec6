// Placeholder until the tensor-tree reader lands (replaced by tensor_tree.cpp).
#include "bsdf/xml_detail.h"

namespace rp::bsdf::detail {
void loadTensorTree(const pugi::xml_node& layer, const XmlContext& ctx, BsdfData&) {
    throw notSupportedYet(ctx.loc(layer), "tensor-tree BSDF data");
}
}  // namespace rp::bsdf::detail
