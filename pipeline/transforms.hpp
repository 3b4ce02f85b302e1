#pragma once
// Moved to util/transforms.hpp (the floor under every module); this forwarding
// header keeps older includes compiling.
#include "util/transforms.hpp"
