// Compile check of the library core without any Arduino core (see Makefile).
//
// Templates are only compiled when instantiated, so this file instantiates
// every public class template explicitly, for every scalar type, and calls the
// free function templates once. A warning anywhere in that code then fails
// the check on avr-g++, host g++ and arm-none-eabi-g++.
//
// CONTRIBUTORS: when you add a class template (or free function template) to
// the library, append its instantiations below, in the section for your area.
#include "TinyParticle.hpp"

namespace tinyparticle {

// ---- Math --------------------------------------------------------------
template class Fixed<16, 16>;
template class Fixed<24, 8>;
template class Fixed<8, 8>;

template struct Vec<Q16_16, 2>;
template struct Vec<Q16_16, 3>;
template struct Vec<Q24_8, 2>;
template struct Vec<Q24_8, 3>;
template struct Vec<Q8_8, 2>;
template struct Vec<Q8_8, 3>;
template struct Vec<Float, 2>;
template struct Vec<Float, 3>;

// ---- World, Forces, Contacts, Render, Loop, Scenes ----------------------
// (append here)

}  // namespace tinyparticle

// Free function templates: called once per scalar so that their bodies are
// compiled. Not meant to run.
template <typename S>
S checkVectorFunctions() {
  tinyparticle::Vec2<S> a(S(1), S(2));
  tinyparticle::Vec3<S> b(S(1), S(2), S(3));
  tinyparticle::Vec3<S> c = cross(b, b);
  return dot(a, a) + cross(a, a) + dot(b, c) + (S(2) * a).x;
}

template tinyparticle::Q16_16 checkVectorFunctions<tinyparticle::Q16_16>();
template tinyparticle::Q24_8 checkVectorFunctions<tinyparticle::Q24_8>();
template tinyparticle::Q8_8 checkVectorFunctions<tinyparticle::Q8_8>();
template tinyparticle::Float checkVectorFunctions<tinyparticle::Float>();
