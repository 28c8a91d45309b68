"""The parametrised exercises of the chapter mobility."""

from ..limbs import revolute
from ..mobility_analysis import grubler_kutzbach, mobility
from . import pick, register

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

#: spatial limbs of three joints: base, leg, platform
SPATIAL_LIMBS = ["RPS", "PRS", "RRS", "UPS", "PUS", "UPU", "RPU", "SPS"]


@register("mobility", 4)
def count_a_spatial_parallel_mechanism(rng):
    limbs = pick(rng, [3, 4, 6], 3)
    limb = pick(rng, SPATIAL_LIMBS, "RPS")
    base, leg, platform = (JOINTS[letter][0] for letter in limb)
    leg = leg.replace("joint", "leg")
    freedoms = sum(JOINTS[letter][1] for letter in limb)
    # the base, the platform and two links per limb; three joints per limb
    count = grubler_kutzbach(
        links=2 + 2 * limbs, joints=3 * limbs, freedoms=limbs * freedoms
    )
    numbers = {"limbs": (limbs, "")} | {
        f"{JOINTS[letter][0].split()[1]} joints per limb": (limb.count(letter), "")
        for letter in JOINTS
    }
    statement = (
        f"Count the freedoms of the {limbs}-{limb} ({WORDS[limbs]} limbs: {base} at "
        f"the base, {leg}, {platform} at the platform) with the Grübler-Kutzbach "
        f"formula."
    )
    return numbers, statement, float(count)


@register("mobility", 5)
def count_a_planar_parallel_mechanism(rng):
    limbs = pick(rng, [2, 3, 4, 5], 3)
    chain = pick(rng, [3, 4], 3)  # revolutes per limb
    count = grubler_kutzbach(
        links=2 + (chain - 1) * limbs, joints=chain * limbs, freedoms=chain * limbs
    )
    numbers = {"limbs": (limbs, ""), "revolutes per limb": (chain, "")}
    statement = (
        f"The planar {limbs}-{'R' * chain} (all {AXES[chain * limbs]} axes vertical) "
        f"moves its platform in its plane with three freedoms. What does the spatial "
        f"Grübler-Kutzbach formula give for it?"
    )
    return numbers, statement, float(count)


def _planar_rrr(i):
    """An RRR limb with vertical axes through three points that are not in line."""
    z = [0, 0, 1]
    return (
        revolute(z, [2 * i, 0, 0])
        + revolute(z, [2 * i + 1, 1, 0])
        + revolute(z, [i, 3, 0])
    )


@register("mobility", 6)
def redundant_constraints_of_a_planar_mechanism(rng):
    limbs = pick(rng, [2, 3, 4, 5, 6, 7], 3)
    found = mobility([_planar_rrr(i) for i in range(limbs)])
    numbers = {"limbs": (limbs, "")}
    statement = (
        f"For the planar {limbs}-RRR (all axes vertical), how many redundant "
        f"constraints nu (the LWS orders summed, minus the PWS order) make up the "
        f"difference between the formula's {found.grubler_kutzbach} and the three "
        f"freedoms?"
    )
    return numbers, statement, float(found.redundant_constraints)
