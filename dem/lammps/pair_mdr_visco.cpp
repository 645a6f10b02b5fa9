/* The mdr contact law as the LAMMPS pair style mdr/visco (see pair_mdr_visco.h and docs/dem.md).
 *
 * A contact of spheres i and j (radii r_i, r_j, equivalent radius R = r_i r_j / (r_i + r_j)) is mdr's rigid sphere of
 * radius R on a half-space with the two materials' creep functions added (eq. 8). The law of a type pair is built
 * once for R = 1 m: a sphere's MDR profile scales as g(x; R) = R g(x / R; 1), so a contact of radius R with overlap
 * d and tangential increment du is the unit contact at d / R and du / R with forces times R^2 (the element forces
 * are a modulus times two lengths); its half-width is given relative to R. The contact's state is its history. */

#include "pair_mdr_visco.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include "mdr/error.hpp"

using namespace LAMMPS_NS;

namespace {

const char *const history_fix = "NEIGH_HISTORY_MDR_VISCO";
const char *const dummy_fix = "NEIGH_HISTORY_MDR_VISCO_DUMMY";


double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void cross(const double *a, const double *b, double *out)
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// Prefetches for writing the line at `address` into the L2 (locality 2: x86-64's prefetcht1; into the L1 as well
// measured 1-2 ns slower beyond the L2 with the chunks, docs/dem-performance.md): a prefetch never faults, and the
// address is formed as an integer, since it may lie past the history page. These helpers are always inlined: GCC 12
// takes a function that only prefetches for one without effect and drops its calls.
[[gnu::always_inline]] inline void prefetch_line(std::uintptr_t address)
{
  __builtin_prefetch(reinterpret_cast<const void *>(address), 1, 2);
}

// The lines at `base` + `offsets`[k] [bytes], k < Count, without a loop.
template <std::size_t... k>
[[gnu::always_inline]] inline void prefetch_lines(std::uintptr_t base, const std::uintptr_t *offsets,
                                                  std::index_sequence<k...>)
{
  (prefetch_line(base + offsets[k]), ...);
}

// The lines at `base` + `offsets`[k], k < count: each count up to twelve has its own sequence (a loop per range
// cost 46 instructions a contact-step without friction, these 24, docs/dem-performance.md; GCC 12 unrolls a loop
// over the count into a chain of compares).
[[gnu::always_inline]] inline void prefetch_lines(std::uintptr_t base, const std::uintptr_t *offsets,
                                                  std::size_t count)
{
  switch (count) {
    case 1: return prefetch_lines(base, offsets, std::make_index_sequence<1>{});
    case 2: return prefetch_lines(base, offsets, std::make_index_sequence<2>{});
    case 3: return prefetch_lines(base, offsets, std::make_index_sequence<3>{});
    case 4: return prefetch_lines(base, offsets, std::make_index_sequence<4>{});
    case 5: return prefetch_lines(base, offsets, std::make_index_sequence<5>{});
    case 6: return prefetch_lines(base, offsets, std::make_index_sequence<6>{});
    case 7: return prefetch_lines(base, offsets, std::make_index_sequence<7>{});
    case 8: return prefetch_lines(base, offsets, std::make_index_sequence<8>{});
    case 9: return prefetch_lines(base, offsets, std::make_index_sequence<9>{});
    case 10: return prefetch_lines(base, offsets, std::make_index_sequence<10>{});
    case 11: return prefetch_lines(base, offsets, std::make_index_sequence<11>{});
    case 12: return prefetch_lines(base, offsets, std::make_index_sequence<12>{});
    default:
      for (std::size_t k = 0; k < count; k++) prefetch_line(base + offsets[k]);
  }
}

// Contacts per chunk of the pair loop (on the stack; 8 measured a little faster than 16 or 32 beyond the L2,
// docs/dem-performance.md).
constexpr int chunk_size = 8;

}    // namespace

// A contact as the pair loop's first pass leaves it for the law's step and the forces (take_steps).
struct PairMdrVisco::Contact {
  int i, j;
  mdr::dem::ContactLaw *law;                 // of the two atoms' types
  double del[3];                             // x_j - x_i
  double scale;                              // R
  mdr::dem::ContactLaw::SpatialStep step;    // the state, d / R, the unit normal from i to j, the increment / R
};

PairMdrVisco::PairMdrVisco(LAMMPS *lmp) : Pair(lmp), fix_history(nullptr), size_history(0)
{
  single_enable = 0;
  no_virial_fdotr_compute = 1;
  finitecutflag = 1;
  restartinfo = 1;
  beyond_contact = 0;
  nextra = 2;    // compute pair mdr/visco: [1] the energy stored in the contacts, [2] the work done on them
  pvector = new double[nextra]{0.0, 0.0};
  nondefault_history_transfer = 1;    // a swapped contact's state is mirrored (transfer_history)
  // a placeholder for the history fix, so that the fixes keep the order of the input script (as pair granular)
  modify->add_fix(std::string(dummy_fix) + " all DUMMY");
}

PairMdrVisco::~PairMdrVisco()
{
  delete[] pvector;
  if (modify->find_fix(fix_history ? history_fix : dummy_fix) >= 0)
    modify->delete_fix(fix_history ? history_fix : dummy_fix);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairMdrVisco::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  materials.assign(n + 1, Material{});
  material_given.assign(n + 1, 0);
  resolutions.assign(static_cast<std::size_t>((n + 1) * (n + 1)), Resolution{});
  laws.clear();
  laws.resize(resolutions.size());
  largest_radius.assign(n + 1, 0.0);
}

void PairMdrVisco::settings(int narg, char **arg)
{
  if (narg != 0) error->all(FLERR, "pair_style mdr/visco takes no arguments (got '{}')", arg[0]);
}

/* pair_coeff I J [G_inf value] [term G tau]... [friction mu] [elements N] [half_width L/R]
 * The material keys set the type's own material and need I = J (a range such as * * sets each type's);
 * friction, elements and half_width set the type pair's law. */
void PairMdrVisco::coeff(int narg, char **arg)
{
  if (narg < 2) error->all(FLERR, "pair_coeff for mdr/visco: give I J and keywords");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  Material material;
  bool has_material = false;
  Resolution given;
  given.given = true;
  bool has_friction = false;
  for (int a = 2; a < narg; a++) {
    const std::string key = arg[a];
    const auto value = [&](int k) {
      if (a + k >= narg) error->all(FLERR, "pair_coeff mdr/visco: {} needs {} value(s)", key, k);
      return utils::numeric(FLERR, arg[a + k], false, lmp);
    };
    if (key == "G_inf") {
      material.equilibrium_modulus = value(1);
      has_material = true;
      a += 1;
    } else if (key == "term") {
      material.terms.push_back({value(1), value(2)});
      a += 2;
    } else if (key == "friction") {
      given.friction = value(1);
      has_friction = true;
      a += 1;
    } else if (key == "elements") {
      const double elements = value(1);
      if (!(elements >= 1.0 && elements <= 1e6 && elements == std::floor(elements)))
        error->all(FLERR, "pair_coeff mdr/visco: elements = {}: must be a whole number in [1, 1e6]", arg[a + 1]);
      given.elements = static_cast<int>(elements);
      a += 1;
    } else if (key == "half_width") {
      given.half_width = value(1);
      a += 1;
    } else {
      error->all(FLERR, "pair_coeff mdr/visco: unknown keyword '{}' (G_inf, term, friction, elements, half_width)",
                 key);
    }
  }
  if (!material.terms.empty() && !has_material)
    error->all(FLERR, "pair_coeff mdr/visco: term needs G_inf (the equilibrium modulus) as well");
  if (!has_friction) error->all(FLERR, "pair_coeff mdr/visco: friction is required (0 for none)");
  // the values' rules are the library's: a law built here reports the first broken one by its name
  try {
    const auto rheology = mdr::rheology::Rheology::prony(has_material ? material.equilibrium_modulus : 1.0,
                                                         material.terms);
    mdr::dem::ContactLaw(rheology, 1.0, given.friction, static_cast<std::size_t>(given.elements), given.half_width,
                         1.0);
  } catch (const mdr::InvalidInput &e) {
    error->all(FLERR, "pair_coeff mdr/visco: {} = {}: {}", e.key(), e.value(), e.rule());
  }

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      if (has_material && i != j) continue;    // a type's material comes from I = J
      if (has_material) {
        materials[i] = material;
        material_given[i] = 1;
      }
      resolutions[pair_index(i, j)] = given;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "pair_coeff mdr/visco: no type pair set (a material needs I = J)");
}

std::size_t PairMdrVisco::pair_index(int i, int j) const
{
  return static_cast<std::size_t>(i * (atom->ntypes + 1) + j);
}

PairMdrVisco::Resolution PairMdrVisco::resolution(int i, int j) const
{
  if (i > j) std::swap(i, j);
  const Resolution &own = resolutions[pair_index(i, j)];
  if (own.given) return own;
  // unlike types without their own pair_coeff: the geometric mean friction (as pair granular), the finer law
  const Resolution &a = resolutions[pair_index(i, i)], &b = resolutions[pair_index(j, j)];
  Resolution mixed;
  mixed.friction = std::sqrt(a.friction * b.friction);
  mixed.elements = std::max(a.elements, b.elements);
  mixed.half_width = std::max(a.half_width, b.half_width);
  return mixed;
}

void PairMdrVisco::build_laws()
{
  const int n = atom->ntypes;
  int largest = 0;
  for (int i = 1; i <= n; i++) {
    if (!material_given[i])
      error->all(FLERR, "pair mdr/visco: type {} has no material; give pair_coeff {} {} G_inf ...", i, i, i);
  }
  for (int i = 1; i <= n; i++) {
    for (int j = i; j <= n; j++) {
      const Resolution r = resolution(i, j);
      try {
        const auto first = mdr::rheology::Rheology::prony(materials[i].equilibrium_modulus, materials[i].terms);
        const auto second = mdr::rheology::Rheology::prony(materials[j].equilibrium_modulus, materials[j].terms);
        laws[pair_index(i, j)] = std::make_unique<mdr::dem::ContactLaw>(
            mdr::rheology::in_series(first, second), 1.0, r.friction, static_cast<std::size_t>(r.elements),
            r.half_width, update->dt);
      } catch (const mdr::InvalidInput &e) {
        error->all(FLERR, "pair mdr/visco: types {} {}: {} = {}: {}", i, j, e.key(), e.value(), e.rule());
      }
      largest = std::max(largest, static_cast<int>(laws[pair_index(i, j)]->state_size()));
    }
  }
  // the law of types (i, j) in either order, read once per contact-step (no min, max and ntypes there)
  law_of_types.assign(resolutions.size(), nullptr);
  for (int i = 1; i <= n; i++)
    for (int j = 1; j <= n; j++)
      law_of_types[pair_index(i, j)] = laws[pair_index(std::min(i, j), std::max(i, j))].get();
  if (fix_history && largest != size_history)
    error->all(FLERR,
               "pair mdr/visco: the coefficients changed the contact state's size ({} to {} doubles) between "
               "runs; keep elements and the number of terms",
               size_history, largest);
  size_history = largest;
}

void PairMdrVisco::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "pair mdr/visco needs atom_style sphere (radius, mass, omega, torque)");
  if (!comm->ghost_velocity) error->all(FLERR, "pair mdr/visco needs ghost velocities: comm_modify vel yes");
  build_laws();

#ifdef MDR_LAMMPS_ADD_REQUEST    // LAMMPS from 2022 on (dem/lammps/CMakeLists.txt finds out)
  neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_HISTORY);
#else
  int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->size = 1;
  neighbor->requests[irequest]->history = 1;
#endif

  if (fix_history == nullptr) {
    fix_history = dynamic_cast<FixNeighHistory *>(modify->replace_fix(
        dummy_fix, std::string(history_fix) + " all NEIGH_HISTORY " + std::to_string(size_history), 1));
    fix_history->pair = this;
  }
  // the history fix reserves pages of `neigh_modify page` contacts up front: say so when that is large
  const double page_bytes = static_cast<double>(neighbor->pgsize) * size_history * sizeof(double);
  if (comm->me == 0 && page_bytes > 100e6)
    error->warning(FLERR,
                   "pair mdr/visco: each contact's history is {} doubles, and a history page of neigh_modify page "
                   "{} contacts reserves {:.0f} MB per rank; set neigh_modify one and page to what the contacts need "
                   "(docs/dem.md)",
                   size_history, neighbor->pgsize, page_bytes / 1e6);
  const int ifix = modify->find_fix(history_fix);
  if (ifix < 0) error->all(FLERR, "pair mdr/visco: its history fix {} is gone", history_fix);
  fix_history = dynamic_cast<FixNeighHistory *>(modify->fix[ifix]);

  // the largest radius of each type sets the cutoff (as pair granular, without fix pour and deposit)
  std::vector<double> local(atom->ntypes + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++) local[atom->type[i]] = std::max(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), largest_radius.data(), atom->ntypes + 1, MPI_DOUBLE, MPI_MAX, world);
}

double PairMdrVisco::init_one(int i, int j)
{
  return largest_radius[i] + largest_radius[j];
}

void PairMdrVisco::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const bool history_update = !update->setupflag;    // setup: the forces of the stored states (as pair granular)

  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const double dt = update->dt;
  int **firsttouch = fix_history->firstflag;
  double **firsthistory = fix_history->firstvalue;
  // the time step is the same for every contact of a step: each type pair's law takes it once, here
  if (history_update) {
    for (const auto &law : laws) {
      if (!law) continue;
      try {
        law->set_time_step(dt);
      } catch (const mdr::InvalidInput &e) {
        error->all(FLERR, "pair mdr/visco: {}", e.what());
      }
    }
  }
  // the doubles at a state's start that every step touches (ContactLaw::held_step_size), the most of any law, and
  // those further on (ContactLaw::held_tangential_offset and _size: with friction the composed tangential step's
  // header and the layer's force and count, without friction the layer's count): the span that covers every law's
  std::size_t leading = 1;
  std::size_t tangential_first = static_cast<std::size_t>(size_history), tangential_last = 0;
  for (const auto &law : laws) {
    if (!law) continue;
    leading = std::max(leading, law->held_step_size());
    tangential_first = std::min(tangential_first, law->held_tangential_offset());
    tangential_last = std::max(tangential_last, law->held_tangential_offset() + law->held_tangential_size());
  }
  // their lines, from a state four entries on, as byte offsets: every eighth double of each range and its last
  // where that is not the eighth before it (beyond the L3 the hardware prefetchers miss them: 4 lines of every 22,
  // docs/dem-performance.md)
  const std::uintptr_t ahead_bytes = 4 * static_cast<std::uintptr_t>(size_history) * sizeof(double);
  std::vector<std::uintptr_t> lines;
  const auto range = [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; k += 8) lines.push_back(ahead_bytes + k * sizeof(double));
    if ((last - 1 - first) % 8 != 0) lines.push_back(ahead_bytes + (last - 1) * sizeof(double));
  };
  range(0, leading);
  if (tangential_last > 0) range(tangential_first, tangential_last);
  // from the far end of the state to its start: the order session 18 measured
  std::reverse(lines.begin(), lines.end());
  const std::uintptr_t *line_offsets = lines.data();
  const std::size_t line_count = lines.size();
  // the contacts' energy for compute pair (docs/dem.md): a contact computed on two ranks (newton off, j a ghost)
  // counts half on each
  double work = 0.0, stored = 0.0;

  // The contacts in chunks of the list's order: first the geometry of each (here), then the laws' steps and the
  // forces (take_steps).
  std::array<Contact, chunk_size> chunk;
  int count = 0;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    int *touch = firsttouch[i];
    double *allhistory = firsthistory[i];
    const int *jlist = list->firstneigh[i];
    // atom i's values, read once for its neighbours
    const double xi[3] = {x[i][0], x[i][1], x[i][2]};
    const double vi[3] = {v[i][0], v[i][1], v[i][2]};
    const double omegai[3] = {omega[i][0], omega[i][1], omega[i][2]};
    const double radiusi = radius[i];
    mdr::dem::ContactLaw *const *laws_of_i = law_of_types.data() + pair_index(type[i], 0);
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      double *history = &allhistory[size_history * jj];
      prefetch_lines(reinterpret_cast<std::uintptr_t>(history), line_offsets, line_count);    // the held lines ahead
      const double del[3] = {x[j][0] - xi[0], x[j][1] - xi[1], x[j][2] - xi[2]};
      const double rsq = dot(del, del);
      const double radsum = radiusi + radius[j];
      if (rsq >= radsum * radsum) {
        // a neighbour out of contact: its state is zeroed where the contact ends (fix neigh/history zeroes every
        // unflagged entry when it builds the lists), so a pair that was not touching is not written again (its
        // 8 size_history bytes each step, where a packing has more such neighbours than contacts)
        if (touch[jj]) std::fill(history, history + size_history, 0.0);
        touch[jj] = 0;
        continue;
      }
      touch[jj] = 1;
      Contact &contact = chunk[count++];
      contact.i = i;
      contact.j = j;
      contact.law = laws_of_i[type[j]];
      mdr::dem::ContactLaw::SpatialStep &step = contact.step;
      step.state = {history, contact.law->state_size()};
      const double r = std::sqrt(rsq);
      for (int k = 0; k < 3; k++) contact.del[k] = del[k];
      for (int k = 0; k < 3; k++) step.normal[k] = del[k] / r;    // from i to j
      contact.scale = radiusi * radius[j] / radsum;                // R: the law is that of R = 1
      step.overlap = (radsum - r) / contact.scale;
      // the contact points' relative velocity: v_i + w_i x (r_i n) - v_j - w_j x (-r_j n)
      double spin[3], turned[3];
      for (int k = 0; k < 3; k++) spin[k] = radiusi * omegai[k] + radius[j] * omega[j][k];
      cross(spin, step.normal.data(), turned);
      for (int k = 0; k < 3; k++) step.increment[k] = (vi[k] - v[j][k] + turned[k]) * dt / contact.scale;
      if (count == chunk_size) {
        take_steps(chunk.data(), count, history_update, work, stored);
        count = 0;
      }
    }
  }
  take_steps(chunk.data(), count, history_update, work, stored);
  if (eflag_global) pvector[0] = stored;
  pvector[1] += work;
}

// The laws' steps of `count` contacts (two contacts at once where both are held: ContactLaw::advance_spatial_pair),
// then their forces, torques and energies in the list's order (so the sums are those of one contact after the other).
void PairMdrVisco::take_steps(const Contact *chunk, int count, bool history_update, double &work, double &stored)
{
  double **f = atom->f, **torque = atom->torque;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  std::array<mdr::dem::ContactLaw::SpatialOutcome, chunk_size> outcomes;    // each written before it is read
  std::array<bool, chunk_size> stepped{};
  if (history_update) {
    for (int c = 0; c + 1 < count; c += 2) {
      if (chunk[c].law != chunk[c + 1].law) continue;
      const std::span<mdr::dem::ContactLaw::SpatialOutcome, 2> pair(outcomes.data() + c, 2);
      stepped[c] = stepped[c + 1] = chunk[c].law->advance_spatial_pair(chunk[c].step, chunk[c + 1].step, pair);
    }
  }
  for (int c = 0; c < count; c++) {
    const Contact &contact = chunk[c];
    const int i = contact.i, j = contact.j;
    mdr::dem::ContactLaw &law = *contact.law;
    const mdr::dem::ContactLaw::SpatialStep &step = contact.step;
    const bool whole = newton_pair || j < nlocal;    // this rank applies the contact to j as well
    mdr::dem::SpatialVector tangential;
    double normal_force = 0.0;
    try {
      if (stepped[c]) {
        tangential = outcomes[c].tangential_force;
      } else if (history_update) {
        tangential = law.advance_spatial(step.state, step.overlap, step.normal, step.increment);
        outcomes[c].work = law.step_work();
      } else {
        law.check(step.state);    // a state read from a restart file is checked once
        tangential = law.tangential_force(step.state, step.normal);
      }
      normal_force = law.normal_force(step.state);
      const double share = whole ? 1.0 : 0.5;
      const double volume = contact.scale * contact.scale * contact.scale;    // the unit contact's energies are R^3
      if (history_update) work += share * volume * outcomes[c].work;
      if (eflag_global) stored += share * volume * law.stored_energy(step.state);
    } catch (const mdr::InvalidInput &e) {
      if (e.key() == "half_width")
        error->one(FLERR,
                   "pair mdr/visco: atoms {} and {} overlap by d/R = {:.4g} (R = {:.4g}): beyond the law's "
                   "half_width {} of types {} {}; give pair_coeff ... half_width >= sqrt(d/R) = {:.3g}",
                   tag[i], tag[j], step.overlap, contact.scale, e.value(), type[i], type[j],
                   std::sqrt(step.overlap));
      error->one(FLERR, "pair mdr/visco: atoms {} and {}: {}", tag[i], tag[j], e.what());
    }
    const double area = contact.scale * contact.scale;
    double fj[3];
    for (int k = 0; k < 3; k++) fj[k] = area * (normal_force * step.normal[k] + tangential[k]);
    for (int k = 0; k < 3; k++) f[i][k] -= fj[k];
    if (whole)
      for (int k = 0; k < 3; k++) f[j][k] += fj[k];
    // the torques are -r_i n x F_t and -r_j n x F_t; a tangential force of zero (no friction, or none yet) leaves
    // them as they are (x - 0 = x; only a torque of -0, which no step of this style leaves, would become +0)
    if (tangential[0] != 0.0 || tangential[1] != 0.0 || tangential[2] != 0.0) {
      const double tangential_force[3] = {area * tangential[0], area * tangential[1], area * tangential[2]};
      double tj[3];
      cross(step.normal.data(), tangential_force, tj);    // n x F_t
      for (int k = 0; k < 3; k++) torque[i][k] -= radius[i] * tj[k];
      if (whole)
        for (int k = 0; k < 3; k++) torque[j][k] -= radius[j] * tj[k];
    }
    if (evflag)    // the force on i and x_i - x_j
      ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, -fj[0], -fj[1], -fj[2], -contact.del[0], -contact.del[1],
                   -contact.del[2]);
  }
}

void PairMdrVisco::transfer_history(double *source, double *target)
{
  std::copy(source, source + size_history, target);
  mdr::dem::ContactLaw::mirror(std::span<double>(target, static_cast<std::size_t>(size_history)));
}

void PairMdrVisco::write_restart(FILE *fp)
{
  const int n = atom->ntypes;
  for (int i = 1; i <= n; i++) {
    const int terms = material_given[i] ? static_cast<int>(materials[i].terms.size()) : -1;
    fwrite(&terms, sizeof(int), 1, fp);
    if (terms < 0) continue;
    fwrite(&materials[i].equilibrium_modulus, sizeof(double), 1, fp);
    for (const auto &term : materials[i].terms) {
      fwrite(&term.modulus, sizeof(double), 1, fp);
      fwrite(&term.relaxation_time, sizeof(double), 1, fp);
    }
  }
  for (int i = 1; i <= n; i++) {
    for (int j = i; j <= n; j++) {
      const Resolution &r = resolutions[pair_index(i, j)];
      const int flags[3] = {setflag[i][j], r.given ? 1 : 0, r.elements};
      fwrite(flags, sizeof(int), 3, fp);
      fwrite(&r.friction, sizeof(double), 1, fp);
      fwrite(&r.half_width, sizeof(double), 1, fp);
    }
  }
}

void PairMdrVisco::read_restart(FILE *fp)
{
  allocate();
  const int n = atom->ntypes;
  const int me = comm->me;
  for (int i = 1; i <= n; i++) {
    int terms = -1;
    if (me == 0) utils::sfread(FLERR, &terms, sizeof(int), 1, fp, nullptr, error);
    MPI_Bcast(&terms, 1, MPI_INT, 0, world);
    if (terms < 0) continue;
    std::vector<double> values(1 + 2 * static_cast<std::size_t>(terms));
    if (me == 0) utils::sfread(FLERR, values.data(), sizeof(double), values.size(), fp, nullptr, error);
    MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, world);
    materials[i].equilibrium_modulus = values[0];
    for (int k = 0; k < terms; k++) materials[i].terms.push_back({values[1 + 2 * k], values[2 + 2 * k]});
    material_given[i] = 1;
  }
  for (int i = 1; i <= n; i++) {
    for (int j = i; j <= n; j++) {
      int flags[3];
      double values[2];
      if (me == 0) {
        utils::sfread(FLERR, flags, sizeof(int), 3, fp, nullptr, error);
        utils::sfread(FLERR, values, sizeof(double), 2, fp, nullptr, error);
      }
      MPI_Bcast(flags, 3, MPI_INT, 0, world);
      MPI_Bcast(values, 2, MPI_DOUBLE, 0, world);
      setflag[i][j] = flags[0];
      Resolution &r = resolutions[pair_index(i, j)];
      r.given = flags[1] != 0;
      r.elements = flags[2];
      r.friction = values[0];
      r.half_width = values[1];
    }
  }
}

double PairMdrVisco::memory_usage()
{
  double bytes = Pair::memory_usage();
  for (const auto &law : laws)
    if (law) bytes += static_cast<double>(law->state_size()) * sizeof(double) * 8.0;    // the workspace, roughly
  return bytes;
}
