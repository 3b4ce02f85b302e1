#pragma once
// The GL state a pass ran with, as JSON, with GL's names: what the stepper
// shows for a pass and `mpr step --state N` prints.
#include <string>

#include "pipeline/gl/gl_context.hpp"

namespace mpr {

std::string glStateJson(const GLContext& gl);

// GL names of the per-fragment enums, for reports.
std::string_view compareFuncName(CompareFunc f);
std::string_view stencilOpName(StencilOp op);
std::string_view blendFactorName(BlendFactor f);

}  // namespace mpr
