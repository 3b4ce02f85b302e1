#pragma once
// A GL matrix stack: a top matrix and the saved ones below it.
#include <vector>

#include "pipeline/draw/mesa_matrix_inverse.hpp"
#include "util/vecmath.hpp"

namespace mpr {

class MatrixStack {
 public:
  explicit MatrixStack(int maxDepth) : maxDepth_(maxDepth), stack_{Mat4(1.0f)}, mesa_(1) {}
  const Mat4& top() const { return stack_.back(); }
  Mat4& top() { return stack_.back(); }
  // Mesa's flags, class and inverse of the top (pushed and popped with it).
  MesaMatrixState& mesaTop() { return mesa_.back(); }
  const MesaMatrixState& mesaTop() const { return mesa_.back(); }
  void analyse() { mesaAnalyse(stack_.back(), mesa_.back()); }  // _math_matrix_analyse of the top
  const Mat4& analysedInverse() {  // then the inverse Mesa keeps
    analyse();
    return mesa_.back().inverse;
  }
  int depth() const { return static_cast<int>(stack_.size()); }
  int maxDepth() const { return maxDepth_; }
  // The matrix a pop would make current; the top itself on an empty stack.
  const Mat4& below() const { return stack_.size() > 1 ? stack_[stack_.size() - 2] : stack_.back(); }
  bool push() {  // false on overflow (GL_STACK_OVERFLOW)
    if (depth() >= maxDepth_) return false;
    // Measured: the pushed copy is classified as if the top had been
    // analysed first (a glMultMatrix before a push no longer leaves the copy
    // general, and a glClipPlane right after the push gets the real inverse).
    analyse();
    stack_.push_back(stack_.back());
    mesa_.push_back(mesa_.back());
    changedSincePush_ = false;
    return true;
  }
  bool pop() {  // false on underflow (GL_STACK_UNDERFLOW)
    if (depth() <= 1) return false;
    stack_.pop_back();
    mesa_.pop_back();
    changedSincePush_ = true;
    return true;
  }
  // Mesa's ChangedSincePush: a pop flushes only after the top was changed.
  bool changedSincePush() const { return changedSincePush_; }
  void markChanged() { changedSincePush_ = true; }

 private:
  int maxDepth_;
  std::vector<Mat4> stack_;
  std::vector<MesaMatrixState> mesa_;
  bool changedSincePush_ = true;
};

}  // namespace mpr
