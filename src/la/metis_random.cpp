#include "la/metis_random.hpp"

#include <dlfcn.h>

#include <array>
#include <cstdlib>

namespace
{
/// glibc's rand() is random() with a state of 128 bytes (TYPE_3: degree 31, separation 3),
/// initially as if seeded with 1; this is the same generator, one per thread.
struct ThreadGenerator
{
  bool active = false;
  bool seeded = false;
  random_data data{}; // initstate_r needs it zeroed
  std::array<char, 128> state{};

  void seed(unsigned int value)
  {
    if (!seeded)
    {
      initstate_r(value, state.data(), state.size(), &data);
      seeded = true;
    }
    else
      srandom_r(value, &data);
  }
  int draw()
  {
    if (!seeded)
      seed(1);
    int32_t value = 0;
    random_r(&data, &value);
    return value;
  }
};

thread_local ThreadGenerator generator;
} // namespace

// The definitions the dynamic linker gives libmetis (see the header). The declarations in
// <cstdlib> are glibc's, noexcept in C++.
extern "C" int rand() noexcept
{
  if (generator.active)
    return generator.draw();
  return static_cast<int>(random());
}

extern "C" void srand(unsigned int seed) noexcept
{
  if (generator.active)
    generator.seed(seed);
  else
    srandom(seed);
}

namespace feticon::la
{
bool thread_private_random_available()
{
  // Libraries' calls resolve in the global scope: if it finds these definitions, so do they.
  static const bool available = dlsym(RTLD_DEFAULT, "rand") == reinterpret_cast<void*>(&rand) &&
      dlsym(RTLD_DEFAULT, "srand") == reinterpret_cast<void*>(&srand);
  return available;
}

ThreadPrivateRandom::ThreadPrivateRandom() : _outer(!generator.active) { generator.active = true; }

ThreadPrivateRandom::~ThreadPrivateRandom()
{
  if (_outer)
    generator.active = false;
}
} // namespace feticon::la
