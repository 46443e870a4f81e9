#!/usr/bin/env python3
"""Lagrange derivation of the 2DOF rocking wall (paper Eq. 3.1-3.8, with the corrections of docs/model.md) with sympy.

Geometry: two rigid bodies of height h/2 and thickness b; the lower body rocks on a pivot at a face
of its base (face sign(q1)), the upper body on a pivot at a face of the mid-height joint (face
sign(q2 - q1)); W1 = W2 = W/2, overburden Wd = psi*W1 at the top's mid-thickness; a spring Kd
between the wall top and a support (far-end displacement u_top); ground acceleration ag toward +x
(d'Alembert force -m*ag).  Small rotations: the potential is expanded to second order, the b*q^2
terms and b in the mass matrix are neglected against h as in the paper.  The result is

    M q'' + K q = p*ag + f_u*u_top + Q,   Q = -dV_hinge/dq,
    V_hinge = cap_b*|q1| + cap_m*|q2 - q1|,

and the constant hinge terms A_i, B_i of the four conditions.

Base force (RockingWall output F_base): the horizontal momentum balance of the two bodies and the
overburden, sum_i m_i (ag + x_i'') = R_base - F_top, where x_i is body i's horizontal displacement
relative to the ground, R_base the ground's reaction on the wall and -F_top the spring's force on
the wall. The wall puts F_base = -R_base on its base:

    F_base = -m_tot*ag - c . q'' - F_top,   m_tot = (W + Wd)/g,   c_j = sum_i m_i dx_i/dq_j,

and c = -p (the load vector of Eq. 3.4 is the same momentum coefficient: d'Alembert).

    derive_equations.py                      print the symbolic results
    derive_equations.py --json FILE [--h .. --b .. --W .. --psi .. --Kd .. --g ..]   also write numbers
"""
import argparse
import json
import sys

import sympy as sp

h, b, W, psi, Kd, g, ag, u = sp.symbols("h b W psi K_d g a_g u_top", positive=True)
q1, q2 = sp.symbols("q1 q2", real=True)
dq1, dq2 = sp.symbols("dq1 dq2", real=True)
W1 = W / 2
Wd = psi * W1

# the four conditions: (sign(q1), sign(q2 - q1))
CONDITIONS = {1: (1, -1), 2: (-1, 1), 3: (1, 1), 4: (-1, -1)}


def rot(v, q):
    """Rotate a plane vector clockwise by q (clockwise positive, the top moving toward +x)."""
    x, y = v
    return sp.Matrix([x * sp.cos(q) + y * sp.sin(q), -x * sp.sin(q) + y * sp.cos(q)])


def positions(sb, sm):
    """Absolute positions (x, y) of the lower-body centroid G1, upper-body centroid G2 and the
    top mid-thickness point T (where Wd and the spring act), for pivot faces sb (base), sm (mid)."""
    P0 = sp.Matrix([sb * b / 2, 0])                       # base pivot (body frame = world at q = 0)
    G1 = P0 + rot(sp.Matrix([0, h / 4]) - P0, q1)
    Pc_body = sp.Matrix([sm * b / 2, h / 2])              # mid-height pivot on the joint
    Pc = P0 + rot(Pc_body - P0, q1)
    G2 = Pc + rot(sp.Matrix([0, 3 * h / 4]) - Pc_body, q2)
    T = Pc + rot(sp.Matrix([0, h]) - Pc_body, q2)
    return G1, G2, T


def second_order(expr):
    """Taylor expansion to second order in (q1, q2)."""
    e = sp.symbols("e")
    s = sp.series(expr.subs({q1: e * q1, q2: e * q2}), e, 0, 3).removeO()
    return sp.expand(s.subs(e, 1))


def derive():
    out = {}
    # kinetic energy: T = 1/2 sum m v^2 + 1/2 I w^2, at q = 0 (small rotations), b -> 0 (paper)
    G1, G2, T = positions(1, -1)
    qs, dqs = [q1, q2], [dq1, dq2]
    def vel(P):
        return P.jacobian(qs) * sp.Matrix(dqs)
    I = (W1 / g) * (h / 2) ** 2 / 12                       # centroidal inertia of a body (b neglected)
    Tkin = (W1 / g) * (vel(G1).dot(vel(G1)) + vel(G2).dot(vel(G2))) / 2 + (Wd / g) * vel(T).dot(vel(T)) / 2 \
        + I * (dq1**2 + dq2**2) / 2
    Tkin = Tkin.subs({q1: 0, q2: 0, b: 0})
    M = sp.Matrix(2, 2, lambda i, j: sp.simplify(sp.diff(Tkin, dqs[i], dqs[j])))
    out["M"] = M

    conds = {}
    K = None
    p = fu = None
    for c, (sb, sm) in CONDITIONS.items():
        G1, G2, T = positions(sb, sm)
        top0 = T.subs({q1: 0, q2: 0})[0]
        V = W1 * G1[1] + W1 * G2[1] + Wd * T[1] \
            + Kd * (T[0] - top0 - u) ** 2 / 2 \
            + (ag / g) * (W1 * G1[0] + W1 * G2[0] + Wd * T[0])   # d'Alembert: ground accel. toward +x
        V2 = second_order(V)
        # neglect b against h in the second-order terms (b*q^2, b*q*u, b*q*ag): keep b only at first order in q
        poly = sp.Poly(V2, q1, q2)
        Vs = 0
        for (i, j), coeff in poly.terms():
            coeff = sp.expand(coeff)
            if i + j == 2:
                coeff = coeff.subs(b, 0)
            elif i + j == 1:
                # split: gravity terms linear in q (the hinges) keep b; ag/u terms lose b (b q ag, b q u)
                coeff = sp.expand(coeff)
                keep = sum(t for t in sp.Add.make_args(coeff) if not t.has(ag) and not t.has(u))
                rest = sum(t for t in sp.Add.make_args(coeff) if t.has(ag) or t.has(u))
                coeff = keep + sp.expand(rest).subs(b, 0)
            Vs += coeff * q1**i * q2**j
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
    # hinge capacities: V_hinge = cap_b |q1| + cap_m |q2 - q1|  =>  condition 3 (q1>0, x>0): A = -cap_b + cap_m, B = -cap_m
    A3, B3 = conds[3]
    out["cap_m"] = sp.factor(-B3)
    out["cap_b"] = sp.factor(-A3 + out["cap_m"])
    out.update(base_force(p))
    return out


def base_force(p):
    """F_base = -m_tot*ag - c . q'' - F_top from the horizontal momentum of the bodies and the
    overburden (small rotations, b -> 0 as in M). Returns the coefficients and the residual of
    the identity c = -p, which must be 0."""
    G1, G2, T = positions(1, -1)
    qs = [q1, q2]
    masses = [(W1 / g, G1), (W1 / g, G2), (Wd / g, T)]
    c = sp.zeros(1, 2)
    for m, P in masses:
        c += m * P[0:1, 0].jacobian(qs).subs({q1: 0, q2: 0, b: 0})
    m_tot = sp.simplify(sum(m for m, _ in masses))
    return {"base_mass": m_tot, "base_per_qdd": c.applyfunc(sp.factor),
            "base_identity": sp.simplify(c.T + p)}


def doherty_hinge_reduction(d):
    """dohertyHinge along the simply supported shape q2 = -q1 (docs/model.md "Hinge laws").

    Each hinge's normalised moment is mu(D) = c(D)/F_r of its own mid-height displacement
    (D = h q1/2 at the base, h|x|/4 at mid-height, equal along q2 = -q1), with
    c(D) = Doherty's trilinear force less the gravity slope F_r/Delta_u. Along the shape the 2DOF
    must be Doherty's 1DOF (W/3g) D'' = -(W/2g) ag + F(D): the mass, the load and the gravity
    stiffness from the Lagrange matrices, and the hinges' generalised force on D, in every branch
    of the trilinear law. Returns {name: sympy expression that must be 0}."""
    D, c = sp.symbols("D c", positive=True)                   # mid-height displacement, hinge force
    Du = b * (1 + sp.Rational(3, 4) * psi) / (1 + psi)           # Table 5.1
    Fr = 2 * b / h * W * (1 + sp.Rational(3, 4) * psi)
    shape = sp.Matrix([2 / h, -2 / h])                           # dq/dD along q2 = -q1
    M, K, p = d["M"], d["K"], d["p_per_ag"]
    grav = K.subs(Kd, 0)                                          # the spring does no work along the shape
    checks = {
        "mass W/(3g)": sp.simplify((shape.T * M * shape)[0] - W / (3 * g)),
        "load -(W/(2g)) ag": sp.simplify((shape.T * p)[0] + W / (2 * g)),
        "spring does no work": sp.simplify((shape.T * (K - grav) * shape)[0]),
        # gravity stiffness along the shape is -F_r/Delta_u (the line F_r(1 - D/Delta_u) of the law)
        "gravity slope -F_r/Delta_u": sp.simplify((shape.T * grav * shape)[0] + Fr / Du),
    }
    # hinges: Q = -grad V, V = cap_b*Phi_b(q1) + cap_m*Phi_m(x) with dPhi/dz = mu = c/F_r; along the
    # shape mu_b = mu, mu_m = -mu (x = -2 q1), so the force on D is shape . Q with Q from mu
    mu = c / Fr
    Q = sp.Matrix([-d["cap_b"] * mu + d["cap_m"] * (-mu), -d["cap_m"] * (-mu)])
    checks["hinge force on D = -c(D)"] = sp.simplify((shape.T * Q)[0] + c)
    # with the gravity line, -c(D) + (F_r/Delta_u) D is Doherty's trilinear -F(D) in each branch
    D1, D2, Fi = sp.symbols("Delta_1 Delta_2 F_i", positive=True)
    branches = {"D <= Delta_1": ((Fi / D1 + Fr / Du) * D, Fi * D / D1),
                "Delta_1 < D <= Delta_2": (Fi + Fr / Du * D, Fi),
                "D > Delta_2": (Fr, Fr * (1 - D / Du))}
    for name, (c_branch, trilinear) in branches.items():
        checks[f"branch {name}"] = sp.simplify(c_branch - Fr / Du * D - trilinear)
    return checks


def numbers(d, vals):
    subs = {h: vals["h"], b: vals["b"], W: vals["W"], psi: vals["psi"], Kd: vals["Kd"], g: vals["g"]}
    f = lambda e: float(sp.N(e.subs(subs)))
    return {
        "params": vals,
        "M": [[f(d["M"][i, j]) for j in range(2)] for i in range(2)],
        "K": [[f(d["K"][i, j]) for j in range(2)] for i in range(2)],
        "p_per_ag": [f(d["p_per_ag"][i]) for i in range(2)],
        "fu_per_u": [f(d["fu_per_u"][i]) for i in range(2)],
        "conditions": {str(c): {"A": f(A), "B": f(B)} for c, (A, B) in d["conditions"].items()},
        "cap_b": f(d["cap_b"]),
        "cap_m": f(d["cap_m"]),
        "base_mass": f(d["base_mass"]),
        "base_per_qdd": [f(d["base_per_qdd"][j]) for j in range(2)],
    }


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--json", metavar="FILE", help="write numeric values for the parameters below")
    ap.add_argument("--h", type=float, default=2.5)
    ap.add_argument("--b", type=float, default=0.15)
    ap.add_argument("--W", type=float, default=6622.0)
    ap.add_argument("--psi", type=float, default=0.5)
    ap.add_argument("--Kd", type=float, default=1e5)
    ap.add_argument("--g", type=float, default=9.81)
    ap.add_argument("--quiet", action="store_true", help="do not print the symbolic results")
    a = ap.parse_args(argv)
    d = derive()
    if not a.quiet:
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
        print(f"\ncap_b = {d['cap_b']},  cap_m = {d['cap_m']}")
        print("\nBase force F_base = -m_tot*ag - c . q'' - F_top (force of the wall on its base, +x):")
        print(f"  m_tot = {d['base_mass']},  c = {list(d['base_per_qdd'])}")
        print(f"  c + p (must be 0): {list(d['base_identity'])}")
    reduction = doherty_hinge_reduction(d)
    if not a.quiet:
        print("\ndohertyHinge along q2 = -q1 reduces to Doherty's 1DOF (each residual must be 0):")
        for name, residual in reduction.items():
            print(f"  {name}: {residual}")
    bad = {k: v for k, v in reduction.items() if v != 0}
    if d["base_identity"] != sp.zeros(2, 1):
        bad["base force coefficients c = -p"] = d["base_identity"]
    if bad:
        print(f"derivation checks failed (dohertyHinge reduction, base force): {bad}", file=sys.stderr)
        return 1
    if a.json:
        vals = dict(h=a.h, b=a.b, W=a.W, psi=a.psi, Kd=a.Kd, g=a.g)
        with open(a.json, "w") as fh:
            json.dump(numbers(d, vals), fh, indent=2)
        print(f"wrote {a.json}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
