"""Independent references for the parametrised exercises of jacobians: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

import math

INDEPENDENT = {}


def tip_velocity(n):
    # differentiate x = l1 c1 + l2 c12, y = l1 s1 + l2 s12 by hand
    l1, l2 = n["l1"][0], n["l2"][0]
    q1, q12 = math.radians(n["q1"][0]), math.radians(n["q1"][0] + n["q2"][0])
    d1, d2 = n["qdot1"][0], n["qdot2"][0]
    xdot = -l1 * math.sin(q1) * d1 - l2 * math.sin(q12) * (d1 + d2)
    ydot = l1 * math.cos(q1) * d1 + l2 * math.cos(q12) * (d1 + d2)
    return [xdot, ydot]


def torques_of_the_push(n):
    # a vertical force -F at the tip: each torque is (x_tip - x_joint) (-F); the
    # second link is horizontal, so the tip is l2 to the right of joint 2
    l1, l2, q1, force = n["l1"][0], n["l2"][0], math.radians(n["q1"][0]), n["F"][0]
    return [-(l1 * math.cos(q1) + l2) * force, -l2 * force]


def elbow_rate(n):
    # r rdot = -l1 l2 sin(q2) q2dot with rdot = -speed
    l1, l2, q2, speed = n["l1"][0], n["l2"][0], math.radians(n["q2"][0]), n["speed"][0]
    r = math.sqrt(l1**2 + l2**2 + 2 * l1 * l2 * math.cos(q2))
    return r * speed / (l1 * l2 * math.sin(q2))


INDEPENDENT[10] = tip_velocity
INDEPENDENT[14] = torques_of_the_push
INDEPENDENT[22] = elbow_rate
