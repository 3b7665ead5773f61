// TinyParticle: a small particle physics engine for 8-bit microcontrollers.
// This header declares everything inside namespace tinyparticle; sketches
// usually include <TinyParticle.h>, which also imports the namespace.
#pragma once

#include "TinyParticle/Configuration.hpp"
#include "TinyParticle/Math/MathErrors.hpp"
#include "TinyParticle/Math/Fixed.hpp"
#include "TinyParticle/Math/FixedMath.hpp"
#include "TinyParticle/Math/Float.hpp"
#include "TinyParticle/Math/Vec.hpp"
#include "TinyParticle/Text/Print.hpp"
#include "TinyParticle/Platform/Arduino.hpp"
#include "TinyParticle/Debug/Debug.hpp"
#include "TinyParticle/Debug/Profile.hpp"
#include "TinyParticle/World/World.hpp"
#include "TinyParticle/Loop/RealTimeLoop.hpp"
#include "TinyParticle/Render/AsciiRenderer.hpp"
#include "TinyParticle/Scenes/Lever.hpp"
#include "TinyParticle/Scenes/Pendulum.hpp"
#include "TinyParticle/Scenes/Spring.hpp"
#include "TinyParticle/Scenes/BouncingBalls.hpp"
#include "TinyParticle/Scenes/Chain.hpp"
#include "TinyParticle/Scenes/Cradle.hpp"
