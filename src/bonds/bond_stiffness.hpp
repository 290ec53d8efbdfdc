#pragma once
/// The stiffness set of Chen's unified bond law (Tables 8-9). Every bond model reduces to these four
/// numbers plus a contact-point rule; they are computed once per bond, at creation.
namespace bpm {

struct BondStiffness {
  double k_n = 0.0;    ///< normal (axial) stiffness, N/m
  double k_s = 0.0;    ///< shear stiffness, N/m
  double k_tor = 0.0;  ///< twisting stiffness, N m/rad
  double k_ben = 0.0;  ///< bending stiffness, N m/rad
};

}  // namespace bpm
