#pragma once
/// @file The CalculiX .dat file: what ccx prints for *NODE PRINT, *EL PRINT and *CONTACT PRINT,
/// in its layout, so that scripts written for ccx's .dat read feticon's.
///
/// Layout (ccx 2.20, printout.f / printoutnode.f / printoutint.f / printoutelem.f; checked
/// against the .dat ccx writes for a two-block contact deck, see
/// tests/unit/io/test_dat_writer.cpp). Per output time and request, in the order of the deck:
///   blank line, header, blank line, rows:
///   " displacements (vx,vy,vz) for set NSET and time  0.1000000E+01"   (time: Fortran E14.7)
///   rows I10 node label, 3 x (1X, 1PE13.6)                               (U)
///   " forces (fx,fy,fz) for set NSET and time ..." and the same rows    (RF, TOTALS=NO/YES)
///   " total force (fx,fy,fz) for set NSET and time ...", one row 6X, 3 x (1X, 1PE13.6), the sum
///   over the set                                                         (RF, TOTALS=YES/ONLY)
///   " stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set ELSET and time ..."
///   " strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz) for set ELSET and time ..."
///   rows I10 element label, 1X, I3 integration point, 6 x (1X, 1PE13.6)   (S, E)
///   " contact stress (slave node,press,tang1,tang2) for all contact elements and time 0.1..."
///   " relative contact displacement (slave node,normal,tang1,tang2) for all contact elements and
///   time ...", rows I10 slave node label, 3 x (1X, 1PE13.6)              (CSTR, CDIS)
/// Nodes and elements of a set are printed in increasing label order, as ccx sorts its sets.
/// Note the component orders: CalculiX prints xz before yz; feticon's arrays hold yz before zx.
/// Integration points are numbered as CalculiX's gauss3d2 (xi fastest, then eta, then zeta).
/// Contact output has the layout of ccx's node-to-surface contact (one row per slave node);
/// feticon's contact is frictionless, so tang1 and tang2 of CSTR are 0.
///
/// Departures from ccx: a request without NSET=/ELSET= (ccx ignores it with a warning) prints
/// all nodes as set NALL or all elements as set EALL; CDIS prints tang1 and tang2 as 0 (the
/// tangential relative displacement is not computed) and add_step() says so once.
///
/// Usage:
///   DatWriter dat(out / "model.dat", model);
///   for each load step: warnings += dat.add_step({.time = t, .displacement = u, ...},
///                                               deck.steps[s].outputs);

#include "fem/node_frames.hpp"
#include "io/deck.hpp"
#include "io/fixed_width.hpp"
#include "io/result_labels.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace feticon::io
{
/// @brief The numbering and sets of the model, fixed over the run.
struct DatModel
{
  int32_t n_nodes = 0;
  int32_t n_cells = 0;
  Labels node_labels;    ///< deck number of every mesh node; empty: 1..n_nodes
  Labels element_labels; ///< deck number of every mesh cell; empty: 1..n_cells
  /// Node sets by deck name (upper case), mesh node indices.
  std::map<std::string, std::vector<int32_t>> node_sets;
  /// Element sets by deck name (upper case), mesh cell indices.
  std::map<std::string, std::vector<int32_t>> element_sets;
  /// The rows of *CONTACT PRINT: slave nodes of all contact pairs (mesh node indices), as ccx
  /// lists the slave nodes that have a contact element.
  std::vector<int32_t> contact_slave_nodes;
  /// Local systems of nodes (*TRANSFORM): *NODE PRINT gives their U and RF in local components
  /// unless GLOBAL=YES, each such row marked " L" as ccx's printoutnode.f marks it.
  fem::NodeFrames frames;
};

/// @brief Results of one output time, plain arrays in mesh order. An empty span means "not
/// available": a request for it prints nothing and add_step() returns a warning.
struct DatStep
{
  double time = 0.0;                    ///< total time of the deck (start time of the step + step time)
  std::span<const double> displacement; ///< n_nodes x 3 (m), node-major: U
  /// n_nodes x 3 (N): RF as CalculiX defines it, f_int(u) - f_contact (internal nodal force
  /// minus the contact force on the body; ccx counts its contact springs as elements), i.e. the
  /// support reactions plus the nodal loads: ~0 at free nodes, contact nodes included.
  std::span<const double> reaction_force;
  /// The integration points: those of cell c are point_offsets[c] to point_offsets[c + 1], in
  /// the order CalculiX prints them (n_cells + 1 entries; empty: no point output)
  std::span<const int64_t> point_offsets;
  /// points x 6 Cauchy stress (Pa), components xx yy zz xy yz zx: S
  std::span<const double> stress;
  /// points x 6 strain, tensor components (xy = gamma_xy / 2): E
  std::span<const double> strain;
  /// per point equivalent plastic strain (empty: no plastic body): PEEQ
  std::span<const double> plastic_strain;
  std::span<const double> contact_pressure; ///< n_nodes (Pa), >= 0: CSTR
  std::span<const double> contact_gap;      ///< n_nodes (m), normal gap, < 0 penetration: CDIS
};

/// @brief Writes the .dat file of a run step by step (see the file comment).
class DatWriter
{
public:
  /// @brief Creates `path` (empty; replaces an older file; parent directories are created).
  /// @throws feticon::Error if a label vector has the wrong size, a label is outside
  ///   [1, 9999999999] (the I10 field), a set holds an index outside the mesh, or the file
  ///   cannot be created.
  DatWriter(const std::filesystem::path& path, DatModel model);
  DatWriter(const DatWriter&) = delete;
  DatWriter& operator=(const DatWriter&) = delete;

  /// @brief Prints the *NODE PRINT, *EL PRINT and *CONTACT PRINT requests of `requests`
  /// (others are skipped) for one output time, in their order, and flushes.
  /// @return warnings not returned before, one line per request naming its position: variables
  ///   feticon does not compute or that `step` does not hold (nothing is printed for them).
  /// @throws feticon::Error if a request names an unknown set or a span has the wrong size.
  std::vector<std::string> add_step(const DatStep& step, const std::vector<DeckOutputRequest>& requests);

  /// Closes the file; further add_step() calls throw.
  void close();

  const std::filesystem::path& path() const { return _path; }

private:
  void print_nodal(TextFileBuffer& file, const DatStep& step, const DeckOutputRequest& request,
                   std::string& unavailable);
  /// A node's row of a vector (3 values at `values`): in its local components, marked " L",
  /// if it has a frame and `global` is false.
  void append_vector_row(std::string& out, int32_t node, const double* values, bool global) const;
  void print_integration_points(TextFileBuffer& file, const DatStep& step, const DeckOutputRequest& request,
                                std::string& unavailable);
  void print_contact(TextFileBuffer& file, const DatStep& step, const DeckOutputRequest& request,
                     std::string& unavailable);
  /// Members of a node or element set in increasing label order (cached).
  const std::vector<int32_t>& sorted_set(bool nodes, const std::string& name, const std::string& where);

  std::filesystem::path _path;
  CFile _file;
  DatModel _model;
  std::map<std::pair<bool, std::string>, std::vector<int32_t>> _sorted_sets;
  std::vector<int32_t> _sorted_slaves;
  std::set<std::string> _warned;
};
} // namespace feticon::io
