#include "mesh/mesh_cache.hpp"

#include "mesh/gmsh_module.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/log.hpp"

#include <elf.h>
#include <link.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <system_error>
#include <vector>

namespace feticon::mesh
{
namespace
{
constexpr char magic[] = "feticon mesh cache 2\n";

struct Fnv1a
{
  uint64_t hash = 14695981039346656037ull;
  void add(const char* data, size_t size)
  {
    for (size_t k = 0; k < size; ++k)
    {
      hash ^= static_cast<unsigned char>(data[k]);
      hash *= 1099511628211ull;
    }
  }
  std::string hex() const
  {
    std::ostringstream out;
    out << std::hex << std::setw(16) << std::setfill('0') << hash;
    return out.str();
  }
};

/// The GNU build id of the executable (hex), empty if it has none.
std::string executable_build_id()
{
  std::string id;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* data) -> int {
        // The first object is the executable; its notes hold NT_GNU_BUILD_ID.
        auto& out = *static_cast<std::string*>(data);
        for (int h = 0; h < info->dlpi_phnum; ++h)
        {
          const ElfW(Phdr)& header = info->dlpi_phdr[h];
          if (header.p_type != PT_NOTE)
            continue;
          const char* note = reinterpret_cast<const char*>(info->dlpi_addr + header.p_vaddr);
          const char* end = note + header.p_memsz;
          while (note + sizeof(ElfW(Nhdr)) <= end)
          {
            const auto* n = reinterpret_cast<const ElfW(Nhdr)*>(note);
            const char* name = note + sizeof(ElfW(Nhdr));
            const char* desc = name + ((n->n_namesz + 3) & ~3u);
            if (n->n_type == NT_GNU_BUILD_ID && n->n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0)
            {
              std::ostringstream hex;
              for (unsigned k = 0; k < n->n_descsz; ++k)
                hex << std::hex << std::setw(2) << std::setfill('0')
                    << static_cast<int>(static_cast<unsigned char>(desc[k]));
              out = hex.str();
              return 1;
            }
            note = desc + ((n->n_descsz + 3) & ~3u);
          }
        }
        return 1; // only the executable
      },
      &id);
  return id;
}

// Binary writing and reading of the mesh (native byte order: the cache is per machine).
template <class T>
void put(std::string& out, const T& value)
{
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}
void put_string(std::string& out, const std::string& s)
{
  put<uint64_t>(out, s.size());
  out += s;
}
template <class T>
void put_vector(std::string& out, const std::vector<T>& v)
{
  put<uint64_t>(out, v.size());
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

/// Cells as their kinds and their node lists back to back (the offsets follow from the kinds),
/// faces as the kind and eight node slots: plain integers, no padding bytes in the checksum.
using CachedFace = std::array<int32_t, 9>;

std::vector<uint8_t> cell_kinds(const CellList& cells)
{
  std::vector<uint8_t> out(cells.size());
  for (size_t c = 0; c < cells.size(); ++c)
    out[c] = static_cast<uint8_t>(cells.kind(c));
  return out;
}

std::vector<int32_t> cell_node_entries(const CellList& cells)
{
  std::vector<int32_t> out;
  out.reserve(cells.n_node_entries());
  for (const std::span<const int32_t> cell : cells)
    out.insert(out.end(), cell.begin(), cell.end());
  return out;
}

std::vector<CachedFace> cached_faces(const std::vector<Face>& faces)
{
  std::vector<CachedFace> out(faces.size());
  for (size_t f = 0; f < faces.size(); ++f)
  {
    out[f][0] = static_cast<int32_t>(faces[f].kind);
    std::copy(faces[f].nodes.begin(), faces[f].nodes.end(), out[f].begin() + 1);
  }
  return out;
}

/// The cell list of cached kinds and nodes; false if they do not fit together or name a node
/// outside [0, n_nodes).
bool restore_cells(const std::vector<uint8_t>& kinds, const std::vector<int32_t>& nodes, int32_t n_nodes,
                   CellList& cells)
{
  size_t at = 0;
  cells.reserve(kinds.size(), nodes.size());
  for (const uint8_t kind : kinds)
  {
    if (kind >= all_cell_kinds.size())
      return false;
    const auto n = static_cast<size_t>(cell_nodes(static_cast<CellKind>(kind)));
    if (nodes.size() - at < n)
      return false;
    const std::span<const int32_t> cell(nodes.data() + at, n);
    if (!std::ranges::all_of(cell, [n_nodes](int32_t id) { return id >= 0 && id < n_nodes; }))
      return false;
    cells.add(static_cast<CellKind>(kind), cell);
    at += n;
  }
  return at == nodes.size();
}

std::string serialize(const Mesh& mesh)
{
  std::string out;
  put<uint64_t>(out, static_cast<uint64_t>(mesh.nodes.rows()));
  out.append(reinterpret_cast<const char*>(mesh.nodes.data()), mesh.nodes.size() * sizeof(double));
  put_vector(out, cell_kinds(mesh.cells));
  put_vector(out, cell_node_entries(mesh.cells));
  put_vector(out, mesh.cell_body);
  put<uint64_t>(out, mesh.body_names.size());
  for (const std::string& name : mesh.body_names)
    put_string(out, name);
  put<uint64_t>(out, mesh.node_sets.size());
  for (const auto& [name, nodes] : mesh.node_sets)
  {
    put_string(out, name);
    put_vector(out, nodes);
  }
  put<uint64_t>(out, mesh.face_sets.size());
  for (const auto& [name, faces] : mesh.face_sets)
  {
    put_string(out, name);
    put_vector(out, cached_faces(faces));
  }
  // Generated and Gmsh meshes have one formulation (only decks mix them).
  FETICON_CHECK(mesh.body_planar.empty(), "mesh cache: a mesh of several 2D formulations is not cached");
  put<uint8_t>(out, static_cast<uint8_t>(mesh.planar.kind));
  put<double>(out, mesh.planar.thickness);
  return out;
}

/// Reads what serialize wrote; false on any inconsistency (the entry is then a miss).
class Reader
{
public:
  /// Reads data[first, end) (default: all of it).
  explicit Reader(const std::string& data, size_t first = 0, size_t end = std::string::npos)
      : _data(data), _at(first), _end(std::min(end, data.size()))
  {
  }
  template <class T>
  bool get(T& value)
  {
    if (_end - _at < sizeof(T))
      return false;
    std::memcpy(&value, _data.data() + _at, sizeof(T));
    _at += sizeof(T);
    return true;
  }
  bool get_bytes(void* target, uint64_t count, uint64_t size)
  {
    if (size != 0 && count > (_end - _at) / size)
      return false;
    if (count * size > 0)
      std::memcpy(target, _data.data() + _at, count * size);
    _at += count * size;
    return true;
  }
  bool get_string(std::string& s)
  {
    uint64_t size = 0;
    if (!get(size) || size > _end - _at)
      return false;
    s.assign(_data, _at, size);
    _at += size;
    return true;
  }
  template <class T>
  bool get_vector(std::vector<T>& v)
  {
    uint64_t size = 0;
    if (!get(size) || size > (_end - _at) / sizeof(T))
      return false;
    v.resize(size);
    return get_bytes(v.data(), size, sizeof(T));
  }
  template <class T>
  bool get_named_vectors(std::map<std::string, std::vector<T>>& sets)
  {
    uint64_t count = 0;
    if (!get(count) || count > _data.size())
      return false;
    for (uint64_t k = 0; k < count; ++k)
    {
      std::string name;
      if (!get_string(name) || !get_vector(sets[name]))
        return false;
    }
    return true;
  }
  bool at_end() const { return _at == _end; }

private:
  const std::string& _data;
  size_t _at;
  size_t _end;
};

bool deserialize(const std::string& data, Mesh& mesh)
{
  Reader in(data);
  uint64_t rows = 0;
  if (!in.get(rows) || rows > data.size() / (3 * sizeof(double)))
    return false;
  mesh.nodes.resize(static_cast<Eigen::Index>(rows), 3);
  std::vector<uint8_t> kinds;
  std::vector<int32_t> cell_nodes;
  if (!in.get_bytes(mesh.nodes.data(), 3 * rows, sizeof(double)) || !in.get_vector(kinds) ||
      !in.get_vector(cell_nodes) || !in.get_vector(mesh.cell_body))
    return false;
  uint64_t count = 0;
  if (!in.get(count) || count > data.size())
    return false;
  mesh.body_names.resize(count);
  for (std::string& name : mesh.body_names)
    if (!in.get_string(name))
      return false;
  std::map<std::string, std::vector<CachedFace>> face_sets;
  if (!in.get_named_vectors(mesh.node_sets) || !in.get_named_vectors(face_sets))
    return false;
  // Ids in range, so that a damaged entry that passed the checksum cannot crash a later step.
  const auto n = static_cast<int32_t>(rows);
  const auto in_range = [n](int32_t id) { return id >= 0 && id < n; };
  if (!restore_cells(kinds, cell_nodes, n, mesh.cells))
    return false;
  for (const auto& [name, faces] : face_sets)
    for (const CachedFace& face : faces)
    {
      if (face[0] < 0 || face[0] > static_cast<int32_t>(FaceKind::line3))
        return false;
      const auto kind = static_cast<FaceKind>(face[0]);
      mesh.face_sets[name].push_back(Face(kind, std::span<const int32_t>(face.data() + 1, face_nodes(kind))));
    }
  for (const auto& [name, nodes] : mesh.node_sets)
    if (!std::ranges::all_of(nodes, in_range))
      return false;
  for (const auto& [name, faces] : mesh.face_sets)
    for (const Face& face : faces)
      if (!std::ranges::all_of(face, in_range))
        return false;
  uint8_t planar = 0;
  if (!in.get(planar) || planar > static_cast<uint8_t>(PlanarKind::axisymmetric) || !in.get(mesh.planar.thickness))
    return false;
  mesh.planar.kind = static_cast<PlanarKind>(planar);
  const auto bodies = static_cast<int32_t>(mesh.body_names.size());
  return in.at_end() && mesh.cell_body.size() == mesh.cells.size() &&
      std::ranges::all_of(mesh.cell_body, [bodies](int32_t b) { return b >= 0 && b < bodies; });
}

/// File content: magic, key, payload, checksum of key and payload.
std::string entry_content(const std::string& key, const std::string& payload)
{
  std::string out = magic;
  put_string(out, key);
  put_string(out, payload);
  Fnv1a sum;
  sum.add(out.data(), out.size());
  put(out, sum.hash);
  return out;
}

bool read_entry(const std::filesystem::path& path, const std::string& key, Mesh& mesh)
{
  std::ifstream file(path, std::ios::binary);
  if (!file)
    return false;
  const std::string data((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const size_t magic_size = sizeof(magic) - 1;
  if (data.size() < magic_size + sizeof(uint64_t) || data.compare(0, magic_size, magic) != 0)
    return false;
  Fnv1a sum;
  sum.add(data.data(), data.size() - sizeof(uint64_t));
  uint64_t stored = 0;
  std::memcpy(&stored, data.data() + data.size() - sizeof(uint64_t), sizeof(uint64_t));
  if (stored != sum.hash)
    return false;
  Reader in(data, magic_size, data.size() - sizeof(uint64_t));
  std::string stored_key, payload;
  if (!in.get_string(stored_key) || stored_key != key || !in.get_string(payload) || !in.at_end())
    return false;
  Mesh read;
  if (!deserialize(payload, read))
    return false;
  mesh = std::move(read);
  return true;
}

/// Removes the least recently used entries while the folder holds more than the limit.
void prune(const std::filesystem::path& folder, std::uintmax_t limit_bytes)
{
  std::error_code error;
  struct Entry
  {
    std::filesystem::path path;
    std::filesystem::file_time_type time;
    std::uintmax_t size;
  };
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  for (const auto& item : std::filesystem::directory_iterator(folder, error))
  {
    if (item.path().extension() != ".mesh")
      continue;
    std::error_code e1, e2;
    const auto size = item.file_size(e1);
    const auto time = item.last_write_time(e2);
    if (e1 || e2)
      continue;
    entries.push_back({item.path(), time, size});
    total += size;
  }
  std::ranges::sort(entries, {}, &Entry::time);
  for (const Entry& entry : entries)
  {
    if (total <= limit_bytes)
      break;
    if (std::filesystem::remove(entry.path, error))
      total -= entry.size;
  }
}

} // namespace

MeshCacheLocation mesh_cache_location()
{
  MeshCacheLocation location;
  const char* setting = std::getenv("FETICON_MESH_CACHE");
  if (setting && std::string(setting) == "off")
    return location;
  if (setting && *setting)
    location.folder = setting;
  else if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    location.folder = std::filesystem::path(xdg) / "feticon" / "meshes";
  else if (const char* home = std::getenv("HOME"); home && *home)
    location.folder = std::filesystem::path(home) / ".cache" / "feticon" / "meshes";
  else
    return location;
  location.build_id = executable_build_id();
  location.enabled = !location.build_id.empty();
  location.build_id += " gmsh module " + gmsh_module_stamp();
  return location;
}

Mesh cached_mesh(const MeshCacheLocation& location, const std::string& key, const std::function<Mesh()>& build,
                 bool* hit)
{
  if (hit)
    *hit = false;
  if (!location.enabled)
    return build();
  const std::string full_key = key + "\nbuild " + location.build_id;
  Fnv1a name;
  name.add(full_key.data(), full_key.size());
  const std::filesystem::path path = location.folder / (name.hex() + ".mesh");
  Mesh mesh;
  if (read_entry(path, full_key, mesh))
  {
    std::error_code error; // the time of last use orders the pruning
    std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), error);
    if (hit)
      *hit = true;
    return mesh;
  }
  mesh = build();
  try
  {
    write_file_atomically(path, entry_content(full_key, serialize(mesh)));
    prune(location.folder, location.limit_bytes);
  }
  catch (const Error& error)
  {
    log::warning("mesh cache: " + std::string(error.what()) +
                 "; set FETICON_MESH_CACHE to a writable folder, or to off");
  }
  return mesh;
}

Mesh cached_mesh(const std::string& key, const std::function<Mesh()>& build, bool* hit)
{
  return cached_mesh(mesh_cache_location(), key, build, hit);
}

std::string file_digest(const std::filesystem::path& path)
{
  std::ifstream file(path, std::ios::binary);
  FETICON_CHECK(file, "cannot read '" << path.string() << "'");
  Fnv1a sum;
  std::vector<char> buffer(1 << 16);
  while (file)
  {
    file.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    sum.add(buffer.data(), static_cast<size_t>(file.gcount()));
  }
  FETICON_CHECK(file.eof(), "cannot read '" << path.string() << "'");
  return sum.hex();
}
} // namespace feticon::mesh
