#pragma once
// Probes moved to framebuffer/script_probe.hpp (scenes use them too, and the
// scene model stands below the pipeline); this forwarding header keeps the
// old include working.
#include "framebuffer/script_probe.hpp"
