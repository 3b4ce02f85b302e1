#pragma once
// Moved to util/spelling.hpp (the floor under every module); this forwarding
// header keeps older includes compiling.
#include "util/spelling.hpp"
