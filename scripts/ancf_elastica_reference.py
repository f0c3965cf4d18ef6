#!/usr/bin/python3
# Reference values for the ANCF elastica validation (docs/validation.md,
# "ANCF beams"): a cantilever of unit length and EI = 1, clamped along x,
# with a tip load P of fixed vertical direction. Solves the inextensible
# elastica theta'' = -P cos(theta), theta(0) = 0, theta'(1) = 0 by shooting
# (RK4, 2000 steps, secant on theta'(0)) and prints the tip deflection w/L,
# the axial shortening u/L = 1 - x_tip/L and the tip rotation for
# PL^2/EI = 1..10; these reproduce Mattiasson (1981), Table 1.
import numpy as np
# cantilever, clamped at s=0 along x, tip vertical load P (down) at s=1 (L=1, EI=1)
# theta' = m(s)/EI ; m(s) = P (x_tip - x(s)) ; equivalently theta'' = -P cos(theta), theta(0)=0, theta'(1)=0
def solve(P, guess):
    # unknown c = theta'(0); integrate y=(theta, theta', x, y)
    def f(s, y):
        return np.array([y[1], -P*np.cos(y[0]), np.cos(y[0]), np.sin(y[0])])
    def integ(c, n=2000):
        y = np.array([0.0, c, 0.0, 0.0]); h = 1.0/n
        for i in range(n):
            k1=f(0,y); k2=f(0,y+h/2*k1); k3=f(0,y+h/2*k2); k4=f(0,y+h*k3)
            y = y + h/6*(k1+2*k2+2*k3+k4)
        return y
    c0, c1 = guess*0.999, guess
    g0 = integ(c0)[1]; g1 = integ(c1)[1]
    for it in range(50):
        c2 = c1 - g1*(c1-c0)/(g1-g0)
        c0,g0 = c1,g1; c1=c2; g1=integ(c1)[1]
        if abs(g1)<1e-13: break
    y = integ(c1)
    return y, c1
guess = 0.9
for P in range(1,11):
    y, guess = solve(float(P), guess * P / max(P - 1, 1) if P > 1 else 0.9)
    print(P, "w/L=%.6f  u/L=%.6f tip angle=%.6f" % (abs(y[3]), 1-y[2], abs(y[0])))
