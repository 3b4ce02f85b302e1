#pragma once
// Moved to util/vecmath.hpp (the floor under every module); this forwarding
// header keeps older includes compiling.
#include "util/vecmath.hpp"
