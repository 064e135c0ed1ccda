#pragma once
/// \file
/// A gear's body on its shaft: the root diameter that bounds its bore, one formula for the
/// gearbox reader's default bore and the REXS importer's.

#include "geardyn/geometry/gear.h"

namespace geardyn {

/// Root diameter of the gear cut by its basic rack, d_f = m_n z / cos β − 2 m_n (h_f* − x)
/// (ISO 21771 with the rack's dedendum h_f*) [m].
double rootDiameter(const GearSpec& gear);

}  // namespace geardyn
