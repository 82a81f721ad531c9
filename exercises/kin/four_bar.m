% Four-bar linkage: the loop closure (1) solved by Newton-Raphson at theta2,
% then angular velocities (4) and accelerations (5) from the Jacobian.
% Unknowns q = [theta3; theta4]; O2 = (0,0), O4 = (d,0).
wrap = @(x) x - 2*pi*round(x/(2*pi)) + 2*pi*((x - 2*pi*round(x/(2*pi))) <= -pi);   % to (-pi, pi]
Phi = @(q) [a*cos(theta2) + b*cos(q(1)) - c*cos(q(2)) - d;
            a*sin(theta2) + b*sin(q(1)) - c*sin(q(2))];
J = @(q) [-b*sin(q(1)),  c*sin(q(2));
           b*cos(q(1)), -c*cos(q(2))];
% the assembly: C where the circles about B (radius b) and O4 (radius c) meet,
% left of the line from B to O4 for 'open', right of it for 'crossed'
B = a*[cos(theta2); sin(theta2)];
u = [d; 0] - B;  e = norm(u);  u = u / e;
along = (b^2 + e^2 - c^2) / (2*e);
h = sqrt(max(b^2 - along^2, 0));
if strcmp(branch, 'open'), side = 1; else, side = -1; end
C = B + along*u + side*h*[-u(2); u(1)];
q = [atan2(C(2) - B(2), C(1) - B(1)); atan2(C(2), C(1) - d)];
q = q + [0.05; -0.05];                 % a little off, so that Newton has work to do
for k = 1:50
  dq = -J(q) \ Phi(q);
  q = q + dq;
  if norm(dq) < 1e-13
    break
  end
end
out.theta3 = wrap(q(1));
out.theta4 = wrap(q(2));
% velocities (4): J q' = nu, nu = -dPhi/dtheta2 (per unit omega2)
nu = [a*sin(theta2); -a*cos(theta2)];
w = J(q) \ nu;
out.omega3 = omega2 * w(1);
out.omega4 = omega2 * w(2);
% accelerations (5)
gam = [a*cos(theta2) + b*cos(q(1))*w(1)^2 - c*cos(q(2))*w(2)^2;
       a*sin(theta2) + b*sin(q(1))*w(1)^2 - c*sin(q(2))*w(2)^2];
al = J(q) \ gam;
out.alpha3 = omega2^2 * al(1);
out.alpha4 = omega2^2 * al(2);
% the coupler point P, px along BC and py across it
rp = [cos(q(1)) -sin(q(1)); sin(q(1)) cos(q(1))] * [px; py];
VP = [-B(2); B(1)] + w(1)*[-rp(2); rp(1)];
AP = -B + al(1)*[-rp(2); rp(1)] - w(1)^2*rp;
out.v_P = abs(omega2) * norm(VP);
out.a_P = omega2^2 * norm(AP);
% Freudenstein's equation (2) for theta4, by t = tan(theta4/2): a check
K1 = d/a;  K2 = d/c;  K3 = (a^2 - b^2 + c^2 + d^2) / (2*a*c);
A = cos(theta2) - K1 - K2*cos(theta2) + K3;
Bq = -2*sin(theta2);
Cq = K1 - (K2 + 1)*cos(theta2) + K3;
Q = -(Bq + (2*(Bq >= 0) - 1)*sqrt(max(Bq^2 - 4*A*Cq, 0))) / 2;   % stable: t = Q/A or Cq/Q
t4 = wrap(2*atan2([Q Cq], [A Q]));
fprintf('check: theta4 by Newton %.15g; the roots of Freudenstein %.15g %.15g\n', out.theta4, t4);
% Grashof: shortest + longest <= the other two
Ls = sort([a b c d]);  tol = 4*eps*sum(Ls);
out.grashof = Ls(1) + Ls(4) - Ls(2) - Ls(3) <= tol;
change_point = abs(Ls(1) + Ls(4) - Ls(2) - Ls(3)) <= tol;
% can the crank turn round?  |O4 B| must stay within [|b - c|, b + c]
g1 = abs(d - a) - abs(b - c);  g2 = b + c - d - a;
if abs(g1) <= tol, g1 = 0; end
if abs(g2) <= tol, g2 = 0; end
full = g1 >= 0 && g2 >= 0;
if full
  lo = 0;  hi = 2*pi;
else                                   % the arc between toggles that holds theta2
  uhi = (a^2 + d^2 - (b - c)^2) / (2*a*d);  ulo = (a^2 + d^2 - (b + c)^2) / (2*a*d);
  Ahi = 0;  Alo = pi;
  if uhi < 1, Ahi = acos(uhi); end
  if ulo > -1, Alo = acos(ulo); end
  wt = wrap(theta2);
  if uhi < 1 && ulo > -1
    if wt >= 0, lo = Ahi; hi = Alo; else, lo = -Alo; hi = -Ahi; end
  elseif ulo > -1
    lo = -Alo;  hi = Alo;
  else
    lo = Ahi;  hi = 2*pi - Ahi;
    if wt < 0, wt = wt + 2*pi; end
  end
  lo = lo + theta2 - wt;  hi = hi + theta2 - wt;
  out.theta2_toggle1 = lo;
  out.theta2_toggle2 = hi;
end
% transmission angle (6), by the law of cosines, and its extremes: at the
% ends of |O4 B|'s range, theta2 = 0 and pi (or the toggles)
mu = @(t) acos(max(-1, min(1, (b^2 + c^2 - a^2 - d^2 + 2*a*d*cos(t)) / (2*b*c))));
out.mu = mu(theta2);
cand = [lo hi 0 pi];  mn = Inf;  mx = -Inf;
for i = 1:4
  t = cand(i);  where = cand(i);
  if i > 2
    t = cand(i) + 2*pi*ceil((lo - cand(i)) / (2*pi));   % the first one at or after lo
  end
  if t > hi + 1e-12 || (full && i <= 2)
    continue
  end
  v = mu(t);
  if i <= 2                            % a toggle: coupler and rocker in line
    v = pi * (v >= pi/2);
    where = wrap(t);
  end
  if v < mn, mn = v; tmn = where; end
  if v > mx, mx = v; tmx = where; end
end
out.mu_min = mn;  out.mu_max = mx;
out.theta2_mu_min = tmn;  out.theta2_mu_max = tmx;
% a crank-rocker's swing: theta4 where crank and coupler lie in line
[~, shortest] = min([a b c d]);
if full && ~change_point && shortest == 1
  th4 = [0 0];
  for k = 1:2
    L = b + a*(3 - 2*k);              % stretched b + a, then folded b - a
    ang = acos((L^2 + d^2 - c^2) / (2*L*d));  best = -Inf;
    for sg = [-1 1]
      Cd = L*[cos(sg*ang); sin(sg*ang)];  Bd = Cd * (a*(3 - 2*k)) / L;
      sd = side * ((d - Bd(1))*(Cd(2) - Bd(2)) - (0 - Bd(2))*(Cd(1) - Bd(1)));
      if sd > best, best = sd; th4(k) = atan2(Cd(2), Cd(1) - d); end
    end
  end
  out.rocker_swing = abs(wrap(th4(1) - th4(2)));
end
