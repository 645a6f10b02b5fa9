// Registers the pair style mdr/visco with LAMMPS's plugin command (`plugin load mdrviscoplugin.so`).

#include "lammpsplugin.h"
#include "version.h"

#include "pair_mdr_visco.h"

using namespace LAMMPS_NS;

static Pair *mdr_visco_creator(LAMMPS *lmp) { return new PairMdrVisco(lmp); }

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  auto register_plugin = (lammpsplugin_regfunc) regfunc;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.name = "mdr/visco";
  plugin.info = "mdr's exact viscoelastic contact law (Method of Dimensionality Reduction) for spheres";
  plugin.author = "the mdr project";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &mdr_visco_creator;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);
}
