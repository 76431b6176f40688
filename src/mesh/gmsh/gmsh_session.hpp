#pragma once
/// @file One Gmsh API session: Gmsh is a process-wide singleton that must be initialized
/// without the user's configuration and finalized on every path, also when a call throws.

#include <gmsh.h>

namespace feticon::mesh
{
/// Initializes Gmsh quietly, with errors thrown, and finalizes it when it goes out of scope.
class GmshSession
{
public:
  GmshSession()
  {
    // readConfigFiles = false: a user's ~/.gmshrc or gmsh-options must not change what is read.
    gmsh::initialize(0, nullptr, false);
    try
    {
      gmsh::option::setNumber("General.Terminal", 0);
      // Errors throw (initialize sets this; stated so that no caller depends on the default).
      gmsh::option::setNumber("General.AbortOnError", 2);
    }
    catch (...)
    {
      gmsh::finalize();
      throw;
    }
  }
  ~GmshSession()
  {
    try
    {
      gmsh::finalize();
    }
    catch (...)
    {
      // A destructor must not throw; there is nothing left to clean up.
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

} // namespace feticon::mesh
