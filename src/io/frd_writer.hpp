#pragma once
/// @file CalculiX result file (.frd, ASCII as ccx writes it by default), so that CalculiX
/// GraphiX (cgx) and the tools built on .frd (ccx2paraview, pygccx) read feticon's results.
///
/// Layout (ccx 2.20, frd.c / frdheader.c / frdselect.c; checked against the .frd ccx writes for
/// a two-block contact deck, see tests/unit/io/test_frd_writer.cpp):
///   "    1C", "    1U..." header records (program, date, one 1UMAT per body);
///   "    2C" node block: " -1" I10 label, 3 x %12.5E reference coordinates;
///   "    3C" element block: " -1" I10 label, type 1 (C3D8), group 0, material (body + 1),
///           " -2" 8 x I10 node labels (C3D8 order = VTK hexahedron order);
///   per output time, one result block per field, each "    1PSTEP" (block counter, increment,
///   step), "  100CL" (100 + output number, time, number of nodes), " -4" name, " -5" component
///   lines, " -1" I10 label with %12.5E values, " -3";
///   " 9999" at the end.
/// Values are rounded to float before printing, as ccx does, so every exponent has two digits
/// and the columns stay fixed.
///
/// Fields (ccx's names): DISP (D1 D2 D3), STRESS (SXX SYY SZZ SXY SYZ SZX, nodal), TOSTRAIN
/// (EXX .. EZX, tensor shear components), FORC (F1 F2 F3), CONTACT (COPEN CSLIP1 CSLIP2 CPRESS
/// CSHEAR1 CSHEAR2). Every field is written for all nodes (ccx's surface-to-surface layout; its
/// node-to-surface contact lists only the slave nodes). feticon's contact is frictionless:
/// CSLIP1, CSLIP2, CSHEAR1 and CSHEAR2 are written as 0.
///
/// Crash safety: the file is created with header, nodes and elements; every add_step() writes its
/// blocks over the closing " 9999" and writes it again, then flushes. After each add_step() the
/// file on disk is a complete .frd of the steps so far; a crash during one leaves that step
/// truncated at the end (cgx reads the complete blocks before it).
///
/// Usage:
///   FrdWriter frd(out / "model.frd", mesh, deck.node_labels, deck.element_labels);
///   for each load step: frd.add_step({.time = t, .displacement = u, .stress = s, ...});
///   frd.close();   // or the destructor

#include "io/deck.hpp"
#include "io/fixed_width.hpp"
#include "io/result_labels.hpp"
#include "mesh/mesh.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace feticon::io
{
/// @brief Results of one output time, plain arrays in mesh order, node-major (values of node i
/// at [i * components, (i + 1) * components)). An empty span leaves its field out.
struct FrdStep
{
  double time = 0.0;                        ///< total time of the deck (start time of the step + step time)
  int32_t step = 1;                         ///< the deck's *STEP, 1-based
  int32_t increment = 0;                    ///< increment within the step, 1-based; 0: count the add_step() calls
  std::span<const double> displacement;     ///< n_nodes x 3 (m): DISP
  std::span<const double> stress;           ///< n_nodes x 6 Cauchy (Pa), xx yy zz xy yz zx: STRESS
  std::span<const double> strain;           ///< n_nodes x 6, tensor components (xy = gamma/2),
                                            ///< same order: TOSTRAIN
  std::span<const double> reaction_force;   ///< n_nodes x 3 (N), CalculiX's RF (DatStep): FORC
  std::span<const double> plastic_strain;   ///< n_nodes, the equivalent plastic strain: PE
  std::span<const double> contact_pressure; ///< n_nodes (Pa), >= 0, 0 off contact: CONTACT CPRESS
  /// n_nodes (m), normal gap, < 0 penetration (ccx's sign), 0 off contact: CONTACT COPEN;
  /// empty: COPEN written as 0. Written only with contact_pressure.
  std::span<const double> contact_gap;
};

/// @brief Which fields the deck's *NODE FILE, *EL FILE and *CONTACT FILE requests of a step
/// ask for (the caller passes the corresponding arrays to FrdWriter::add_step).
struct FrdFields
{
  bool displacement = false;   ///< U
  bool reaction_force = false; ///< RF
  bool stress = false;         ///< S
  bool strain = false;         ///< E
  bool plastic_strain = false; ///< PE (equivalent plastic strain)
  bool contact = false;        ///< CDIS or CSTR
};

/// @brief Reads the *_FILE requests of `outputs` (print requests are ignored).
/// @param[out] warnings one line per request, naming its position, for what feticon does not
///   write: variables other than U, RF, S, E, PE, CDIS, CSTR, and NSET=/ELSET= (all nodes are written)
FrdFields frd_fields(const std::vector<DeckOutputRequest>& outputs, std::vector<std::string>& warnings);

/// @brief Writes a CalculiX .frd result file step by step (see the file comment).
class FrdWriter
{
public:
  /// @brief Creates `path` (replacing an older file; parent directories are created) with the
  /// header, nodes and elements, and flushes it.
  /// @param[in] mesh           nodes (m) and cells (he8, te4, te10, he20, pe6); cell_body sets the material number
  /// @param[in] node_labels    deck number of every mesh node; empty: 1..n_nodes
  /// @param[in] element_labels deck number of every mesh cell; empty: 1..n_cells
  /// @throws feticon::Error if a label vector has the wrong size, a label is outside
  ///   [1, 9999999999] (the I10 field), or the file cannot be written.
  FrdWriter(const std::filesystem::path& path, const mesh::Mesh& mesh, const Labels& node_labels = {},
            const Labels& element_labels = {});
  FrdWriter(const FrdWriter&) = delete;
  FrdWriter& operator=(const FrdWriter&) = delete;

  /// @brief Appends the blocks of one output time (DISP, STRESS, TOSTRAIN, FORC, CONTACT: the
  /// non-empty ones, in ccx's order) and flushes. A step without fields writes no block but
  /// still counts as an output time.
  /// @throws feticon::Error naming the field if a span has the wrong size, if the time is
  ///   outside [0, 1e99), or if the file cannot be written.
  void add_step(const FrdStep& step);

  /// Closes the file (it is complete already); further add_step() calls throw.
  void close();

  const std::filesystem::path& path() const { return _path; }
  /// Output times written (CalculiX's "kode").
  int32_t n_steps() const { return _n_steps; }

private:
  void write_block_header(std::string& out, const FrdStep& step, int32_t increment);
  /// The checks of add_step: an open file, the fields' sizes, the step number and the time.
  void check_step(const FrdStep& step) const;
  /// The blocks of the step's non-empty fields, in ccx's order.
  void write_fields(TextFileBuffer& out, const FrdStep& step, int32_t increment);
  /// One block: header, name and component records, then per node `components` values
  /// value(i, k) (k < components).
  template <class Value>
  void write_block(TextFileBuffer& out, const FrdStep& step, int32_t increment, const char* records, int components,
                   Value value);

  std::filesystem::path _path;
  CFile _file;
  Labels _node_labels; ///< empty: 1..n
  int32_t _n_nodes = 0;
  int32_t _n_steps = 0;
  int32_t _n_blocks = 0;    ///< ccx's "icounter" in 1PSTEP
  int32_t _last_step = 0;   ///< deck step of the previous add_step
  int32_t _increment = 0;   ///< add_step calls within _last_step
  long _end_of_results = 0; ///< file offset of the closing " 9999"
};
} // namespace feticon::io
