#include "app/disc_file.hpp"

#include "common/error.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace feticon::app
{
namespace
{
/// The 1-based index of a disc line as a 0-based component, checked against n and the bounds.
la::Index component(const std::string& where, long long index, la::Index n, const la::Vector& lower,
                    const la::Vector& upper, const std::vector<int>& disc_line)
{
  FETICON_CHECK(index >= 1 && index <= n,
                where << "index " << index << " is outside 1.." << n << " (1-based, as the rows of A)");
  const auto i = static_cast<la::Index>(index - 1);
  FETICON_CHECK(disc_line[i] == 0,
                where << "index " << index << " is already in the disc of line " << disc_line[i]
                      << "; a component belongs to one disc at most");
  FETICON_CHECK(std::isinf(lower[i]) && std::isinf(upper[i]),
                where << "index " << index << " has the bounds [" << lower[i] << ", " << upper[i]
                      << "]; a disc component takes no bounds (-inf in l, inf in u)");
  return i;
}
} // namespace

std::vector<qp::Disc> read_disc_file(const std::string& path, la::Index n, const la::Vector& lower,
                                     const la::Vector& upper)
{
  std::error_code ec;
  FETICON_CHECK(std::filesystem::is_regular_file(path, ec),
                path << (std::filesystem::exists(path, ec) ? ": is not a regular file (a folder or a device?)"
                                                           : ": no such disc file"));
  std::ifstream in(path);
  FETICON_CHECK(in, path << ": cannot open the disc file for reading");
  std::vector<qp::Disc> discs;
  std::vector<int> disc_line(static_cast<std::size_t>(n), 0);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number)
  {
    std::istringstream fields(line);
    std::string first;
    if (!(fields >> first) || first[0] == '%' || first[0] == '#')
      continue;
    fields.seekg(0);
    long long i = 0;
    long long j = 0;
    double radius = 0.0;
    std::string rest;
    const std::string where = path + ":" + std::to_string(number) + ": ";
    FETICON_CHECK((fields >> i >> j >> radius) && !(fields >> rest),
                  where << "expected 'i j radius' (two 1-based indices and a number), got '" << line << "'");
    FETICON_CHECK(i != j, where << "index " << i << " twice; a disc joins two components");
    FETICON_CHECK(std::isfinite(radius) && radius >= 0.0,
                  where << "radius " << radius << "; a radius is finite and >= 0");
    const la::Index first_index = component(where, i, n, lower, upper, disc_line);
    disc_line[first_index] = number;
    const la::Index second_index = component(where, j, n, lower, upper, disc_line);
    disc_line[second_index] = number;
    discs.push_back({first_index, second_index, radius});
  }
  FETICON_CHECK(!in.bad(), path << ": read error");
  return discs;
}
} // namespace feticon::app
