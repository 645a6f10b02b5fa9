/* The exact viscoelastic contact law of mdr (Method of Dimensionality Reduction, Popov & Hess) as a LAMMPS granular
 * pair style, built as a plugin (mdr_visco_plugin.cpp). Each contact's mdr state is the contact's LAMMPS history
 * (fix NEIGH_HISTORY), so it follows atoms across processors and into restart files. `compute pair mdr/visco`
 * gives the energy stored in the contacts and the work done on them (pvector). See docs/dem.md. */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(mdr/visco,PairMdrVisco);
// clang-format on
#else

#ifndef LMP_PAIR_MDR_VISCO_H
#define LMP_PAIR_MDR_VISCO_H

#include <memory>
#include <vector>

#include "pair.h"

#include "mdr/dem/contact_law.hpp"
#include "mdr/rheology/rheology.hpp"

namespace LAMMPS_NS {

class PairMdrVisco : public Pair {
 public:
  PairMdrVisco(class LAMMPS *);
  ~PairMdrVisco() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  // LAMMPS before 2023 calls the first, later ones the second (they pass the two atom types)
  virtual void transfer_history(double *, double *);
  virtual void transfer_history(double *source, double *target, int, int) { transfer_history(source, target); }
  double memory_usage() override;

 private:
  /// A type's material: G(t) = G_inf + sum_k G_k exp(-t / tau_k).
  struct Material {
    double equilibrium_modulus = 0.0;
    std::vector<mdr::rheology::RelaxationTerm> terms;
  };
  /// The law's settings of a type pair: given with pair_coeff or mixed from the two types'.
  struct Resolution {
    double friction = 0.0;
    int elements = 20;
    double half_width = 0.2;  ///< L / R_eff: the largest contact radius over the equivalent radius
    bool given = false;
  };

  struct Contact;
  void take_steps(const Contact *, int, bool, double &, double &);
  void allocate();
  void build_laws();
  Resolution resolution(int, int) const;
  std::size_t pair_index(int, int) const;

  std::vector<Material> materials;                          // per type (1-based)
  std::vector<char> material_given;                         // per type
  std::vector<Resolution> resolutions;                      // per type pair, pair_index
  std::vector<std::unique_ptr<mdr::dem::ContactLaw>> laws;  // per type pair, pair_index (i <= j)
  std::vector<mdr::dem::ContactLaw *> law_of_types;         // per type pair, pair_index, both orders
  std::vector<double> largest_radius;                       // per type, for the cutoff
  class FixNeighHistory *fix_history;
  int size_history;    // doubles of history per contact: the largest state of the type pairs' laws
};

}    // namespace LAMMPS_NS

#endif
#endif
