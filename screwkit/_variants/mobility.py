"""The parametrised exercises of the chapter mobility: the keys' computations.

The statements and their draws are in screwkit/answers/mobility.toml.
"""

from ..limbs import revolute
from ..mobility_analysis import grubler_kutzbach, mobility
from . import register

WORDS = {2: "two", 3: "three", 4: "four", 5: "five", 6: "six", 7: "seven"}
AXES = {
    6: "six",
    8: "eight",
    9: "nine",
    12: "twelve",
    15: "fifteen",
    16: "sixteen",
    20: "twenty",
}

#: a joint's letter -> its name in a limb's description and its freedoms
JOINTS = {
    "R": ("a revolute", 1),
    "P": ("a prismatic joint", 1),
    "U": ("a universal joint", 2),
    "S": ("a spherical joint", 3),
}


@register("mobility", 4)
def count_a_spatial_parallel_mechanism(limbs, limb):
    """The Grübler-Kutzbach count of a platform on ``limbs`` limbs ``limb`` (its
    joints' letters from base to platform, "RPS"), and the limb in words."""
    freedoms = sum(JOINTS[letter][1] for letter in limb)
    # the base, the platform and two links per limb; three joints per limb
    count = grubler_kutzbach(
        links=2 + 2 * limbs, joints=3 * limbs, freedoms=limbs * freedoms
    )
    base, leg, platform = (JOINTS[letter][0] for letter in limb)
    shown = {
        f"{JOINTS[letter][0].split()[1]} joints per limb": limb.count(letter)
        for letter in JOINTS
    }
    words = {"limbs_word": WORDS[limbs], "base": base, "platform": platform}
    return count, shown | words | {"leg": leg.replace("joint", "leg")}


@register("mobility", 5)
def count_a_planar_parallel_mechanism(limbs, revolutes):
    """The spatial Grübler-Kutzbach count of a planar mechanism of ``limbs`` limbs of
    ``revolutes`` revolutes each."""
    count = grubler_kutzbach(
        links=2 + (revolutes - 1) * limbs,
        joints=revolutes * limbs,
        freedoms=revolutes * limbs,
    )
    shown = {"limb": "R" * revolutes, "axes": AXES[revolutes * limbs]}
    return count, shown | {"revolutes per limb": revolutes}


def _planar_rrr(i):
    """An RRR limb with vertical axes through three points that are not in line."""
    z = [0, 0, 1]
    return (
        revolute(z, [2 * i, 0, 0])
        + revolute(z, [2 * i + 1, 1, 0])
        + revolute(z, [i, 3, 0])
    )


@register("mobility", 6)
def redundant_constraints_of_a_planar_mechanism(limbs):
    """The redundant constraints of the planar ``limbs``-RRR, and the formula's
    count."""
    found = mobility([_planar_rrr(i) for i in range(limbs)])
    return found.redundant_constraints, {"count": found.grubler_kutzbach}
