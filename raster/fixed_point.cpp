// The rasterizer is header-only (its inner loop is a template over the
// fragment consumer); this unit gives the library an object file.
#include "raster/fixed_point.hpp"
#include "raster/triangle_rasterizer.hpp"
