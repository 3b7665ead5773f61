// TinyParticle umbrella header for sketches: the whole library, with its
// namespace imported. Include <TinyParticle.hpp> instead to keep names
// inside namespace tinyparticle.
#pragma once

#include "TinyParticle.hpp"

using namespace tinyparticle;
