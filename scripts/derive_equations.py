#!/usr/bin/env python3
"""Lagrange derivation of the 2DOF rocking wall (paper Eq. 3.1-3.8, with the corrections of docs/model.md) with sympy.

Geometry: two rigid bodies of height h/2; the lower body rocks on a pivot at distance e_b from the
centreline of its base, on the face sign(q1); the upper body on a pivot at distance e_m from the
centreline of the mid-height joint, on the face sign(q2 - q1) (NZSEE C8's eccentric reactions: the
faces of the effective thickness t = b - 2 pointing by default, e_b = e_m = t/2; the paper has
e_b = e_m = b/2). W1 = W2 = W/2; the overburden Wd = psi*W1 bears on the top at eccentricity e_t
from the centreline (+x positive: the inner face) and moves with the top as mass; the weight-only
overburden Wo = psi_o*W1 bears on the top's centreline and has no mass (walls above, whose mass
their own equations carry). A spring Kd between the top's centreline and a support (far-end
displacement u_top); ground acceleration ag toward +x (d'Alembert force -m*ag). Small rotations:
the potential is expanded to second order, the lever arms are kept at first order in q and
neglected against h in the second-order terms and in the mass matrix, as the paper does with b.
The result is

    M q'' + K q = p*ag + f_u*u_top + Q,   Q = -dV_hinge/dq,
    V_hinge = cap_b(sign q1)*|q1| + cap_m(sign(q2 - q1))*|q2 - q1|,
    cap_b(s) = (2 W1 + Wd + Wo) e_b - s Wd e_t,   cap_m(s) = (W1 + Wd + Wo) e_m - s Wd e_t,

and the constant hinge terms A_i, B_i of the four conditions: the eccentric top load adds Wd*e_t
to every B_i and nothing to the A_i. Along the simply supported shape (q2 = -q1, the top pinned)
the restoring force vanishes at Delta_u(d) per direction d of the mid-height's motion, which is
NZSEE C8's instability displacement Delta_i = A/(2B) of the two-block mechanism (checked here
against its virtual work, written independently).

Base force (RockingWall output F_base): the horizontal momentum balance of the two bodies and the
overburden, sum_i m_i (ag + x_i'') = R_base - F_top, where x_i is body i's horizontal displacement
relative to the ground, R_base the ground's reaction on the wall and -F_top the spring's force on
the wall. The wall puts F_base = -R_base on its base:

    F_base = -m_tot*ag - c . q'' - F_top,   m_tot = (W + Wd)/g,   c_j = sum_i m_i dx_i/dq_j,

and c = -p (the load vector of Eq. 3.4 is the same momentum coefficient: d'Alembert).

    derive_equations.py                      print the symbolic results
    derive_equations.py --json FILE [--h .. --b .. --W .. --psi .. --Kd .. --g .. --pointing ..
        --e-base-ratio .. --e-hinge-ratio .. --e-top .. --psi-weight-only ..]   also write numbers
        (and, under "eccentric", the numbers of a fixed eccentric variant of the same wall)
"""
import argparse
import json
import sys

import sympy as sp

h, b, W, psi, psi_o, Kd, g, ag, u = sp.symbols("h b W psi psi_o K_d g a_g u_top", positive=True)
e_b, e_m = sp.symbols("e_b e_m", positive=True)   # the reactions' distances from the centreline
e_t = sp.symbols("e_t", real=True)                  # the top load's eccentricity, + toward +x
q1, q2 = sp.symbols("q1 q2", real=True)
dq1, dq2 = sp.symbols("dq1 dq2", real=True)
W1 = W / 2
Wd = psi * W1
Wo = psi_o * W1
LEVERS = {e_b: 0, e_m: 0, e_t: 0}
# the paper's wall: reactions on the faces of the full thickness, the top load at mid-thickness, no
# weight-only overburden
PAPER = {e_b: b / 2, e_m: b / 2, e_t: 0, psi_o: 0}

# the four conditions: (sign(q1), sign(q2 - q1))
CONDITIONS = {1: (1, -1), 2: (-1, 1), 3: (1, 1), 4: (-1, -1)}
# the corrected table of docs/model.md before the eccentricities (b the thickness)
PAPER_CONDITIONS = {1: (-(sp.Rational(3, 2) * W1 + Wd) * b, (W1 + Wd) * b / 2),
                    2: ((sp.Rational(3, 2) * W1 + Wd) * b, -(W1 + Wd) * b / 2),
                    3: (-W1 * b / 2, -(W1 + Wd) * b / 2),
                    4: (W1 * b / 2, (W1 + Wd) * b / 2)}


def rot(v, q):
    """Rotate a plane vector clockwise by q (clockwise positive, the top moving toward +x)."""
    x, y = v
    return sp.Matrix([x * sp.cos(q) + y * sp.sin(q), -x * sp.sin(q) + y * sp.cos(q)])


def positions(sb, sm):
    """Absolute positions (x, y) of the lower-body centroid G1, the upper-body centroid G2, the top's
    centreline S (the spring, the weight-only overburden) and the top load's point T, for pivots on
    the faces sb (base), sm (mid-height)."""
    P0 = sp.Matrix([sb * e_b, 0])                         # base pivot (body frame = world at q = 0)
    G1 = P0 + rot(sp.Matrix([0, h / 4]) - P0, q1)
    Pc_body = sp.Matrix([sm * e_m, h / 2])                # mid-height pivot on the joint
    Pc = P0 + rot(Pc_body - P0, q1)
    G2 = Pc + rot(sp.Matrix([0, 3 * h / 4]) - Pc_body, q2)
    S = Pc + rot(sp.Matrix([0, h]) - Pc_body, q2)
    T = Pc + rot(sp.Matrix([e_t, h]) - Pc_body, q2)
    return G1, G2, S, T


def second_order(expr):
    """Taylor expansion to second order in (q1, q2)."""
    e = sp.symbols("e")
    s = sp.series(expr.subs({q1: e * q1, q2: e * q2}), e, 0, 3).removeO()
    return sp.expand(s.subs(e, 1))


def truncated(V2):
    """The lever arms kept at first order in q only, and only in the gravity terms (the hinges):
    neglected against h in the second-order terms and in the terms of ag and u_top (e q ag, e q u)."""
    Vs = 0
    for (i, j), coeff in sp.Poly(V2, q1, q2).terms():
        coeff = sp.expand(coeff)
        if i + j == 2:
            coeff = coeff.subs(LEVERS)
        elif i + j == 1:
            keep = sum(t for t in sp.Add.make_args(coeff) if not t.has(ag) and not t.has(u))
            rest = sum(t for t in sp.Add.make_args(coeff) if t.has(ag) or t.has(u))
            coeff = keep + sp.expand(rest).subs(LEVERS)
        Vs += coeff * q1**i * q2**j
    return Vs


def derive():
    out = {}
    # kinetic energy: T = 1/2 sum m v^2 + 1/2 I w^2, at q = 0 (small rotations), lever arms -> 0
    # (the paper neglects b); the weight-only overburden has no mass
    G1, G2, S, T = positions(1, -1)
    qs, dqs = [q1, q2], [dq1, dq2]
    def vel(P):
        return P.jacobian(qs) * sp.Matrix(dqs)
    I = (W1 / g) * (h / 2) ** 2 / 12                       # centroidal inertia of a body (b neglected)
    Tkin = (W1 / g) * (vel(G1).dot(vel(G1)) + vel(G2).dot(vel(G2))) / 2 + (Wd / g) * vel(T).dot(vel(T)) / 2 \
        + I * (dq1**2 + dq2**2) / 2
    Tkin = Tkin.subs({q1: 0, q2: 0}).subs(LEVERS)
    M = sp.Matrix(2, 2, lambda i, j: sp.simplify(sp.diff(Tkin, dqs[i], dqs[j])))
    out["M"] = M

    conds = {}
    K = None
    p = fu = None
    for c, (sb, sm) in CONDITIONS.items():
        G1, G2, S, T = positions(sb, sm)
        top0 = S.subs({q1: 0, q2: 0})[0]
        V = W1 * G1[1] + W1 * G2[1] + Wd * T[1] + Wo * S[1] \
            + Kd * (S[0] - top0 - u) ** 2 / 2 \
            + (ag / g) * (W1 * G1[0] + W1 * G2[0] + Wd * T[0])   # d'Alembert: ground accel. toward +x
        Vs = truncated(second_order(V))
        grad = sp.Matrix([sp.diff(Vs, q) for q in qs])
        Kc = sp.Matrix(2, 2, lambda i, j: sp.simplify(sp.diff(Vs, qs[i], qs[j])))
        gen = -grad.subs({q1: 0, q2: 0})                   # generalized forces at q = 0
        pc = sp.Matrix([sp.simplify(sp.diff(gen[i], ag)) for i in range(2)])
        fuc = sp.Matrix([sp.simplify(sp.diff(gen[i], u)) for i in range(2)])
        AB = sp.Matrix([sp.simplify(gen[i].subs({ag: 0, u: 0})) for i in range(2)])
        conds[c] = (sp.factor(AB[0]), sp.factor(AB[1]))
        if K is None:
            K, p, fu = Kc, pc, fuc
        else:
            assert sp.simplify(K - Kc) == sp.zeros(2, 2) and sp.simplify(p - pc) == sp.zeros(2, 1)
    out["K"], out["p_per_ag"], out["fu_per_u"], out["conditions"] = K, p, fu, conds
    out.update(capacities(conds))
    out.update(base_force(p))
    return out


def capacities(conds):
    """The hinges' capacities per side from the conditions: Q1 = -cap_b(sb) sb + cap_m(sm) sm,
    Q2 = -cap_m(sm) sm, so cap_m(sm) = -sm B and cap_b(sb) = -sb (A + B). Every side appears in two
    conditions; both must give the same capacity (V_hinge is one potential)."""
    cap_b, cap_m = {}, {}
    for c, (sb, sm) in CONDITIONS.items():
        A, B = conds[c]
        for table, side, value in ((cap_m, sm, -sm * B), (cap_b, sb, -sb * (A + B))):
            value = sp.factor(value)
            assert side not in table or sp.simplify(table[side] - value) == 0, (c, side)
            table[side] = value
    mean_b, mean_m = (sp.factor((t[1] + t[-1]) / 2) for t in (cap_b, cap_m))
    return {"cap_b_side": cap_b, "cap_m_side": cap_m, "cap_b": mean_b, "cap_m": mean_m}


def base_force(p):
    """F_base = -m_tot*ag - c . q'' - F_top from the horizontal momentum of the bodies and the
    overburden (small rotations, lever arms -> 0 as in M; the weight-only overburden has no mass).
    Returns the coefficients and the residual of the identity c = -p, which must be 0."""
    G1, G2, S, T = positions(1, -1)
    qs = [q1, q2]
    masses = [(W1 / g, G1), (W1 / g, G2), (Wd / g, T)]
    c = sp.zeros(1, 2)
    for m, P in masses:
        c += m * P[0:1, 0].jacobian(qs).subs({q1: 0, q2: 0}).subs(LEVERS)
    m_tot = sp.simplify(sum(m for m, _ in masses))
    return {"base_mass": m_tot, "base_per_qdd": c.applyfunc(sp.factor),
            "base_identity": sp.simplify(c.T + p)}


def paper_checks(d):
    """The paper's wall (reactions on the faces of b, the top load at mid-thickness, no weight-only
    overburden) gives the equations as they were before the eccentricities, exactly."""
    Wd_ = psi * W1
    hg = h**2 / g
    old = {
        "M": sp.Matrix([[(W1 / 3 + Wd_ / 4) * hg, (W1 / 8 + Wd_ / 4) * hg],
                        [(W1 / 8 + Wd_ / 4) * hg, (W1 / 12 + Wd_ / 4) * hg]]),
        "K": sp.Matrix([[Kd * h**2 / 4 - sp.Rational(3, 4) * W1 * h - Wd_ * h / 2, Kd * h**2 / 4],
                        [Kd * h**2 / 4, Kd * h**2 / 4 - W1 * h / 4 - Wd_ * h / 2]]),
        "p_per_ag": sp.Matrix([-(3 * W1 + 2 * Wd_) * h / (4 * g), -(W1 + 2 * Wd_) * h / (4 * g)]),
    }
    checks = {f"paper's {k}": sp.simplify(d[k].subs(PAPER) - v) for k, v in old.items()}
    for c, (A, B) in PAPER_CONDITIONS.items():
        checks[f"paper's condition {c}"] = sp.simplify(sp.Matrix(d["conditions"][c]).subs(PAPER) - sp.Matrix([A, B]))
    checks["paper's cap_b"] = sp.simplify(d["cap_b"].subs(PAPER) - (2 * W1 + Wd_) * b / 2)
    checks["paper's cap_m"] = sp.simplify(d["cap_m"].subs(PAPER) - (W1 + Wd_) * b / 2)
    return {k: (v if not isinstance(v, sp.MatrixBase) else (0 if v == sp.zeros(*v.shape) else v))
            for k, v in checks.items()}


def mechanism_delta_i(direction):
    """NZSEE C8's instability displacement of the two-block mechanism by virtual work, written
    from the mechanism alone: the hinge moves D toward `direction`; the lower block turns D/h_b about
    its base pivot, the upper block D/h_t about the top, which does not move horizontally. Each
    weight rises (first order) and drops (second order) by: the lower centroid e_b/h_b, 1/(4 h_b);
    the hinge (e_b + e_m)/h_b, 1/(2 h_b); the upper centroid the hinge's plus e_m/h_t, 1/(4 h_t); a
    top load at eccentricity e toward the motion the hinge's plus (e + e_m)/h_t, 1/(2 h_t).
    V(D) = A D - B D^2, Delta_i = A/(2B)."""
    hb = ht = h / 2
    rise, drop = (e_b + e_m) / hb, 1 / (2 * hb)
    loads = ((Wd, direction * e_t), (Wo, 0))
    A = W1 * e_b / hb + W1 * (rise + e_m / ht) + sum(P * (rise + (e + e_m) / ht) for P, e in loads)
    B = W1 / (4 * hb) + W1 * (drop + 1 / (4 * ht)) + sum(P * (drop + 1 / (2 * ht)) for P, _ in loads)
    return A / (2 * B)


def instability(d):
    """Delta_u(d) of the model per direction d (+1: the mid-height moving toward +x): along the
    simply supported shape q2 = -q1 with rigid hinges (conditions 1 and 2), the displacement
    D = h q1/2 where the static restoring force vanishes; F_r(d) its value at D = 0."""
    D = sp.symbols("D", positive=True)
    shape = sp.Matrix([2 / h, -2 / h])                             # dq/dD along q2 = -q1
    grav = d["K"].subs(Kd, 0)
    out = {}
    for direction, c in ((1, 1), (-1, 2)):
        q = shape * D * direction
        force = -direction * (shape.T * (sp.Matrix(d["conditions"][c]) - grav * q))[0]  # restoring, toward 0
        out[direction] = {"F_r": sp.factor(force.subs(D, 0)), "Delta_u": sp.factor(sp.solve(force, D)[0])}
    return out


def direction_checks(d, inst):
    """Delta_u(d) is C8's Delta_i, and F_r(d) = (2/h)(cap_b(d) + 2 cap_m(-d))."""
    checks = {}
    for direction, v in inst.items():
        checks[f"Delta_u({direction:+d}) = C8's Delta_i"] = sp.simplify(v["Delta_u"] - mechanism_delta_i(direction))
        caps = d["cap_b_side"][direction] + 2 * d["cap_m_side"][-direction]
        checks[f"F_r({direction:+d}) from the capacities"] = sp.simplify(v["F_r"] - 2 / h * caps)
    return checks


def doherty_hinge_reduction(d, inst):
    """dohertyHinge along the simply supported shape q2 = -q1 (docs/model.md "Hinge laws"), in
    each direction of the mid-height's motion.

    Each hinge's normalised moment is mu(D) = c(D)/F_r(d) of its own mid-height displacement
    (D = h q1/2 at the base, h|x|/4 at mid-height, equal along q2 = -q1), with c(D) = Doherty's
    trilinear force of the direction less the gravity slope F_r(d)/Delta_u(d). Along the shape the
    2DOF must be Doherty's 1DOF (W/3g) D'' = -(W/2g) ag + F(D): the mass, the load and the gravity
    stiffness from the Lagrange matrices, and the hinges' generalised force on D, in every branch
    of the trilinear law. Returns {name: sympy expression that must be 0}."""
    D, c = sp.symbols("D c", positive=True)                   # |mid-height displacement|, hinge force
    shape = sp.Matrix([2 / h, -2 / h])                           # dq/dD along q2 = -q1
    M, K, p = d["M"], d["K"], d["p_per_ag"]
    grav = K.subs(Kd, 0)                                          # the spring does no work along the shape
    checks = {
        "mass W/(3g)": sp.simplify((shape.T * M * shape)[0] - W / (3 * g)),
        "load -(W/(2g)) ag": sp.simplify((shape.T * p)[0] + W / (2 * g)),
        "spring does no work": sp.simplify((shape.T * (K - grav) * shape)[0]),
    }
    D1, D2, Fi = sp.symbols("Delta_1 Delta_2 F_i", positive=True)
    for direction, v in inst.items():
        Fr, Du = v["F_r"], v["Delta_u"]
        tag = f" ({direction:+d})"
        # the gravity stiffness along the shape is -F_r/Delta_u (the line F_r(1 - D/Delta_u) of the law)
        checks["gravity slope -F_r/Delta_u" + tag] = sp.simplify((shape.T * grav * shape)[0] + Fr / Du)
        # hinges: Q = -grad V, V = cap_b(sb)*Phi_b(q1) + cap_m(sm)*Phi_m(x), dPhi/dz = mu = c/F_r(d);
        # along the shape toward `direction`: mu_b = direction*mu on the base's side `direction`,
        # mu_m = -direction*mu on the mid-height's side -direction (x = -2 q1)
        mu = c / Fr
        cb, cm = d["cap_b_side"][direction], d["cap_m_side"][-direction]
        Q = sp.Matrix([-cb * direction * mu + cm * (-direction * mu), -cm * (-direction * mu)])
        checks["hinge force on D = -c(D)" + tag] = sp.simplify(direction * (shape.T * Q)[0] + c)
        # with the gravity line, -c(D) + (F_r/Delta_u) D is Doherty's trilinear -F(D) in each branch
        branches = {"D <= Delta_1": ((Fi / D1 + Fr / Du) * D, Fi * D / D1),
                    "Delta_1 < D <= Delta_2": (Fi + Fr / Du * D, Fi),
                    "D > Delta_2": (Fr, Fr * (1 - D / Du))}
        for name, (c_branch, trilinear) in branches.items():
            checks[f"branch {name}" + tag] = sp.simplify(c_branch - Fr / Du * D - trilinear)
    return checks


def lever_values(vals):
    """The lever arms of a parameter set: t = b - 2 pointing, e_b = eBaseRatio t/2, e_m = eHingeRatio t/2."""
    t = vals["b"] - 2 * vals["pointing"]
    return {e_b: vals["eBaseRatio"] * t / 2, e_m: vals["eHingeRatio"] * t / 2, e_t: vals["eTop"]}


def numbers(d, inst, vals):
    subs = {h: vals["h"], b: vals["b"], W: vals["W"], psi: vals["psi"], Kd: vals["Kd"], g: vals["g"],
            psi_o: vals["psiWeightOnly"], **lever_values(vals)}
    f = lambda e: float(sp.N(sp.sympify(e).subs(subs)))
    sides = {"+1": 1, "-1": -1}
    return {
        "params": vals,
        "M": [[f(d["M"][i, j]) for j in range(2)] for i in range(2)],
        "K": [[f(d["K"][i, j]) for j in range(2)] for i in range(2)],
        "p_per_ag": [f(d["p_per_ag"][i]) for i in range(2)],
        "fu_per_u": [f(d["fu_per_u"][i]) for i in range(2)],
        "conditions": {str(c): {"A": f(A), "B": f(B)} for c, (A, B) in d["conditions"].items()},
        "cap_b": f(d["cap_b"]),
        "cap_m": f(d["cap_m"]),
        "cap_b_side": {k: f(d["cap_b_side"][s]) for k, s in sides.items()},
        "cap_m_side": {k: f(d["cap_m_side"][s]) for k, s in sides.items()},
        "F_r": {k: f(inst[s]["F_r"]) for k, s in sides.items()},
        "Delta_u": {k: f(inst[s]["Delta_u"]) for k, s in sides.items()},
        "base_mass": f(d["base_mass"]),
        "base_per_qdd": [f(d["base_per_qdd"][j]) for j in range(2)],
    }


def eccentric_variant(vals):
    """A fixed eccentric variant of a wall, for the tests: pointing 5 % of b on each face, the base
    reaction at 0.8 and the hinge's at 0.9 of t/2 from the centreline, the top load 0.3 b/2 toward
    +x, a weight-only overburden of 0.6 W1."""
    return dict(vals, pointing=0.05 * vals["b"], eBaseRatio=0.8, eHingeRatio=0.9, eTop=0.15 * vals["b"],
                psiWeightOnly=0.6)


def print_results(d, inst, checks):
    sp.init_printing(use_unicode=False)
    print("Mass matrix M (Eq. 3.2):")
    sp.pprint(sp.simplify(d["M"]))
    print("\nStiffness matrix K (Eq. 3.3):")
    sp.pprint(d["K"].applyfunc(sp.expand))
    print("\np_eff per unit ground acceleration (Eq. 3.4, ag positive toward +x):")
    sp.pprint(d["p_per_ag"])
    print("\nf_u per unit top displacement u_top:")
    sp.pprint(d["fu_per_u"])
    print("\nConstant hinge terms A_i (DOF 1), B_i (DOF 2) (Eq. 3.5-3.8 corrected):")
    for c, (A, B) in d["conditions"].items():
        sb, sm = CONDITIONS[c]
        print(f"  condition {c} (q1 {'>' if sb > 0 else '<'} 0, q2 {'>' if sm > 0 else '<'} q1):  A = {A},  B = {B}")
    for s in (1, -1):
        print(f"\ncap_b({s:+d}) = {d['cap_b_side'][s]},  cap_m({s:+d}) = {d['cap_m_side'][s]}", end="")
    print(f"\nmeans: cap_b = {d['cap_b']},  cap_m = {d['cap_m']}")
    print("\nPer direction d of the mid-height's motion (+1: toward +x), along q2 = -q1 (top pinned):")
    for s, v in inst.items():
        print(f"  d = {s:+d}:  F_r = {v['F_r']},  Delta_u = {v['Delta_u']}")
    print("\nBase force F_base = -m_tot*ag - c . q'' - F_top (force of the wall on its base, +x):")
    print(f"  m_tot = {d['base_mass']},  c = {list(d['base_per_qdd'])}")
    print(f"  c + p (must be 0): {list(d['base_identity'])}")
    print("\nChecks (each residual must be 0): the paper's equations at e_b = e_m = b/2, e_t = 0, psi_o = 0;")
    print("Delta_u = C8's Delta_i; dohertyHinge along q2 = -q1 reduces to Doherty's 1DOF:")
    for name, residual in checks.items():
        print(f"  {name}: {residual}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--json", metavar="FILE", help="write numeric values for the parameters below")
    ap.add_argument("--h", type=float, default=2.5)
    ap.add_argument("--b", type=float, default=0.15)
    ap.add_argument("--W", type=float, default=6622.0)
    ap.add_argument("--psi", type=float, default=0.5)
    ap.add_argument("--Kd", type=float, default=1e5)
    ap.add_argument("--g", type=float, default=9.81)
    ap.add_argument("--pointing", type=float, default=0.0)
    ap.add_argument("--e-base-ratio", type=float, default=1.0)
    ap.add_argument("--e-hinge-ratio", type=float, default=1.0)
    ap.add_argument("--e-top", type=float, default=0.0)
    ap.add_argument("--psi-weight-only", type=float, default=0.0)
    ap.add_argument("--quiet", action="store_true", help="do not print the symbolic results")
    a = ap.parse_args(argv)
    d = derive()
    inst = instability(d)
    checks = {**paper_checks(d), **direction_checks(d, inst), **doherty_hinge_reduction(d, inst)}
    if d["base_identity"] != sp.zeros(2, 1):
        checks["base force coefficients c = -p"] = d["base_identity"]
    if not a.quiet:
        print_results(d, inst, checks)
    bad = {k: v for k, v in checks.items() if v != 0}
    if bad:
        print(f"derivation checks failed: {bad}", file=sys.stderr)
        return 1
    if a.json:
        vals = dict(h=a.h, b=a.b, W=a.W, psi=a.psi, Kd=a.Kd, g=a.g, pointing=a.pointing, eBaseRatio=a.e_base_ratio,
                    eHingeRatio=a.e_hinge_ratio, eTop=a.e_top, psiWeightOnly=a.psi_weight_only)
        out = numbers(d, inst, vals)
        out["eccentric"] = numbers(d, inst, eccentric_variant(vals))
        with open(a.json, "w") as fh:
            json.dump(out, fh, indent=2)
        print(f"wrote {a.json}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
