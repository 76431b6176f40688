#pragma once
/// @file METIS's random draws made private to the thread that orders a matrix.
///
/// Debian's METIS 5.1 draws its random numbers from the C library's rand(), one generator
/// for the whole process, and reseeds it with srand() at the start of every call. Two
/// threads ordering at once (CHOLMOD calls METIS inside its analysis of every 3D
/// subdomain) interleave their draws in a timing-dependent order, so the orderings, and with
/// them the round-off of everything after, changed from run to run. This file defines rand()
/// and srand() in the executable, where the dynamic linker binds METIS's calls to them
/// (ELF symbol interposition, as malloc replacements do): outside a ThreadPrivateRandom scope
/// they are glibc's own generator (random() / srandom(), which rand() / srand() are in
/// glibc), inside one they draw from a generator of the calling thread, the same algorithm
/// and state size as glibc's, so each METIS call sees the sequence it would see alone and
/// the analyses can run on several threads with the orderings of a serial run.

namespace feticon::la
{
/// True if the process's rand() and srand() are the ones of this file (the executable was
/// linked with them exported, see CMakeLists.txt); otherwise callers must serialize METIS.
bool thread_private_random_available();

/// While alive, rand() and srand() on the constructing thread use that thread's generator.
class ThreadPrivateRandom
{
public:
  ThreadPrivateRandom();
  ~ThreadPrivateRandom();
  ThreadPrivateRandom(const ThreadPrivateRandom&) = delete;
  ThreadPrivateRandom& operator=(const ThreadPrivateRandom&) = delete;

private:
  bool _outer; ///< the outermost scope on this thread switches the generator back
};
} // namespace feticon::la
