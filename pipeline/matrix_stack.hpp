#pragma once
// A GL matrix stack: a top matrix and the saved ones below it.
#include <vector>

#include "util/vecmath.hpp"

namespace mpr {

class MatrixStack {
 public:
  explicit MatrixStack(int maxDepth) : maxDepth_(maxDepth), stack_{Mat4(1.0f)} {}
  const Mat4& top() const { return stack_.back(); }
  Mat4& top() { return stack_.back(); }
  int depth() const { return static_cast<int>(stack_.size()); }
  int maxDepth() const { return maxDepth_; }
  bool push() {  // false on overflow (GL_STACK_OVERFLOW)
    if (depth() >= maxDepth_) return false;
    stack_.push_back(stack_.back());
    return true;
  }
  bool pop() {  // false on underflow (GL_STACK_UNDERFLOW)
    if (depth() <= 1) return false;
    stack_.pop_back();
    return true;
  }

 private:
  int maxDepth_;
  std::vector<Mat4> stack_;
};

}  // namespace mpr
