#ifndef hrcontact_support_mismatch_h
#define hrcontact_support_mismatch_h

#include <hrcontact/core/results.h>

namespace hrcontact
{
  /**
   * How far u_h misses the prescribed displacements between the nodes: the
   * largest |u_h - u_D| at Gauss points of the held faces, relative to the
   * largest |u_h| (every process). The hypercircle needs a kinematically
   * admissible u_h; Q1 meets a prescribed value exactly only where it is
   * linear along each face (bilinear in 3D), so a prescription such as y^2
   * leaves its interpolation error out of the bound. Zero for zero,
   * constant or linear values.
   */
  template <int dim>
  double
  support_mismatch(const Results<dim> &results);
} // namespace hrcontact

#endif
