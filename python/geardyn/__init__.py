"""geardyn: gear-pair and geared-rotor dynamics.

From gear geometry to mesh stiffness, dynamic response, spectra and identification. The compiled
core lives in ``geardyn._geardyn``; this package re-exports it and adds plotting helpers.

>>> import geardyn
>>> pinion = geardyn.Gear(teeth=25, module=3e-3, face_width=0.02)
>>> gear = geardyn.Gear(teeth=30, module=3e-3, face_width=0.02)
>>> round(geardyn.GearPair(pinion=pinion, gear=gear).contact_ratio_transverse, 7)
1.6325826
"""

from ._geardyn import (  # noqa: F401  (re-exported API)
    Gear,
    GearGeometry,
    GearPair,
    __version__,
    config_reference,
    load_config,
)

__all__ = ["Gear", "GearGeometry", "GearPair", "__version__", "config_reference", "load_config"]
