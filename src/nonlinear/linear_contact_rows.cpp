#include "nonlinear/linear_contact_rows.hpp"

#include "common/error.hpp"

#include "contact/contact_row_builder.hpp"

#include <algorithm>
#include <limits>

namespace feticon::nonlinear
{
namespace
{
/// Linearized gaps g_i - |b_i| B_i u (m) of every row; the reference gaps for u empty.
la::Vector linearized_gaps(const contact::ContactConstraints& rows, const la::Vector& u)
{
  la::Vector gap = rows.c;
  if (u.size() > 0)
    gap -= rows.B * u;
  for (la::Index i = 0; i < gap.size(); ++i)
    gap(i) *= rows.row_norm[i];
  return gap;
}
} // namespace

LinearContactRows::LinearContactRows(const mesh::Mesh& mesh, const std::vector<std::string>& masters,
                                     contact::ContactConstraints candidates, double band)
    : _candidates(std::move(candidates))
{
  const auto n = static_cast<size_t>(_candidates.n_rows());
  _band_gap.resize(n);
  // Each pair's contact level is its own: bodies apart in one pair do not hide another's rows.
  std::vector<double> smallest(masters.size(), std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < n; ++i)
  {
    const int32_t p = _candidates.pair[i];
    const std::vector<mesh::Face>& faces = mesh.face_set(masters[p]);
    _band_gap[i] =
        band * contact::face_size(contact::current_face_geometry(mesh, {}, faces[_candidates.master_face[i]]));
    smallest[p] = std::min(smallest[p], _candidates.gap[i]);
  }
  _selected.resize(n);
  for (size_t i = 0; i < n; ++i)
    _selected[i] = _candidates.gap[i] < std::max(smallest[_candidates.pair[i]], 0.0) + _band_gap[i];
}

contact::ContactConstraints LinearContactRows::selected_rows(const la::Vector& u) const
{
  std::vector<char> keep = _selected;
  for (size_t i = 0; i < keep.size(); ++i)
    keep[i] = keep[i] && in_force(static_cast<la::Index>(i));
  return subset(keep, u);
}

bool LinearContactRows::expand(const la::Vector& u)
{
  const la::Vector gap = linearized_gaps(_candidates, u);
  bool penetrates = false;
  for (la::Index i = 0; i < gap.size(); ++i)
    penetrates |= !_selected[i] && in_force(i) && gap(i) < 0;
  if (!penetrates)
    return false;
  for (la::Index i = 0; i < gap.size(); ++i)
    _selected[i] |= in_force(i) && gap(i) < _band_gap[i];
  return true;
}

la::Vector LinearContactRows::all_multipliers(const contact::ContactConstraints& selected,
                                              const la::Vector& lambda) const
{
  la::Vector all = la::Vector::Zero(_candidates.n_rows());
  la::Index k = 0;
  for (la::Index i = 0; i < all.size() && k < lambda.size(); ++i)
    if (_candidates.key(i) == selected.key(k))
      all(i) = lambda(k++);
  return all;
}

int64_t LinearContactRows::n_selected() const { return std::count(_selected.begin(), _selected.end(), 1); }

std::vector<int32_t> LinearContactRows::selected_indices() const
{
  std::vector<int32_t> out;
  for (size_t i = 0; i < _selected.size(); ++i)
    if (_selected[i])
      out.push_back(static_cast<int32_t>(i));
  return out;
}

void LinearContactRows::select(const std::vector<int32_t>& indices)
{
  std::ranges::fill(_selected, 0);
  for (const int32_t i : indices)
  {
    FETICON_CHECK(i >= 0 && i < std::ssize(_selected),
                  "restart: the checkpoint selects contact row " << i << " of " << _selected.size() << " candidates");
    _selected[i] = 1;
  }
}

contact::ContactConstraints LinearContactRows::subset(const std::vector<char>& keep, const la::Vector& u) const
{
  const contact::ContactConstraints& all = _candidates;
  contact::ContactConstraints out = contact::without_rows(all);
  const la::Vector gap = linearized_gaps(all, u);
  contact::ContactRowBuilder rows;
  for (la::Index i = 0; i < all.n_rows(); ++i)
    if (keep[i])
      rows.copy(all, i, gap(i), all.pair[i]);
  rows.finish(all.B.cols(), out);
  return out;
}
} // namespace feticon::nonlinear
