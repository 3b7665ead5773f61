// Hello: the smallest TinyParticle sketch. A ball dropped from 2 m is
// integrated in Q16.16 fixed point (semi-implicit Euler, 50 ms steps) and its
// height is drawn as a bar of '#' on the Serial monitor (115200 baud) until it
// reaches the ground.
#include <TinyParticle.h>

void setup() {
  Serial.begin(115200);
  while (!Serial);
  Serial.println(F("Hello from TinyParticle: a ball falls from 2 m."));

  const Q16_16 gravity(-9.81);  // m/s^2
  const Q16_16 dt(0.05);        // s
  Q16_16 height(2.0);           // m
  Q16_16 speed;                 // m/s, starts at rest
  for (int step = 0; height > Q16_16(); ++step) {
    speed += gravity * dt;      // velocity first,
    height += speed * dt;       // then position with the new velocity
    Serial.print(step * 50);
    Serial.print(F(" ms "));
    for (int i = 0; i < (height * Q16_16(20)).toInt(); ++i) Serial.print('#');
    Serial.println();
  }
  Serial.println(F("Landed."));
}

void loop() {}
