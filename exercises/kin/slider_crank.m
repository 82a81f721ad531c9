% Slider-crank: the loop closure (1) solved by Newton-Raphson at phi,
% then velocity (4) and acceleration (5) from the Jacobian.
% Unknowns q = [theta3; x]: the rod angle and the slider position.
Phi = @(q) [r*cos(phi) + l*cos(q(1)) - q(2);
            r*sin(phi) + l*sin(q(1)) - e];
J = @(q) [-l*sin(q(1)), -1;
           l*cos(q(1)),  0];
q = [0; r*cos(phi) + l];          % a rough guess: the rod level, slider to the right
for k = 1:50
  dq = -J(q) \ Phi(q);
  q = q + dq;
  if norm(dq) < 1e-13 * (1 + norm(q))
    break
  end
end
s = e - r*sin(phi);
if ~(q(2) >= r*cos(phi) - 1e-9*l) || any(~isfinite(q))
  % that guess found the other assembly (slider left of the pin): start
  % again from where the rod's circle meets the slide
  xg = r*cos(phi) + sqrt(max(l^2 - s^2, 0));
  q = [atan2(s, xg - r*cos(phi)); xg];
  for k = 1:50
    dq = -J(q) \ Phi(q);
    q = q + dq;
    if norm(dq) < 1e-13 * (1 + norm(q))
      break
    end
  end
end
% velocities per unit crank angle: J q' = nu, nu = -dPhi/dphi      (4)
nu = [r*sin(phi); -r*cos(phi)];
qd = J(q) \ nu;
% accelerations: J q'' = gamma                                     (5)
gam = [r*cos(phi) + l*cos(q(1))*qd(1)^2;
       r*sin(phi) + l*sin(q(1))*qd(1)^2];
qdd = J(q) \ gam;
out.theta3 = q(1);
out.x = q(2);
out.v = omega * qd(2);
out.a = omega^2 * qdd(2);
out.omega3 = omega * qd(1);
out.alpha3 = omega^2 * qdd(1);
% the closed form (2) as a check
x_closed = r*cos(phi) + sqrt(max(l^2 - s^2, 0));
fprintf('check: x by Newton %.15g, closed form %.15g\n', q(2), x_closed);
if abs(e) + r <= l
  % dead centres (6): crank and rod in line
  out.phi_outer = asin(e/(l + r));
  out.phi_inner = pi + asin(e/(l - r));
  out.x_max = sqrt((l + r)^2 - e^2);
  out.x_min = sqrt((l - r)^2 - e^2);
  out.stroke = out.x_max - out.x_min;
  % quick return (7)
  beta = asin(e/(l - r)) - asin(e/(l + r));
  out.time_ratio = (pi + abs(beta)) / (pi - abs(beta));
else
  % toggles (8): the rod square to the slide, sin(phi) = (e -+ l)/r; the
  % crank rocks on the arc between the two next to phi
  up = (e + l)/r;  dn = (e - l)/r;  base = [];
  if up < 1, base = [base, asin(up), pi - asin(up)]; end
  if dn > -1, base = [base, asin(dn), -pi - asin(dn)]; end
  c = [];
  for i = 1:numel(base)
    for k = -3:3
      c(end + 1) = phi + (base(i) - phi) - 2*pi*round((base(i) - phi)/(2*pi)) + 2*pi*k;
    end
  end
  c = sort(c);
  k = 1;
  while k + 1 < numel(c) && c(k + 1) <= phi
    k = k + 1;
  end
  sm = e - r*sin((c(k) + c(k + 1))/2);
  if (l - sm)*(l + sm) < 0                % phi on the rounding edge of a gap
    if phi - c(k) < c(k + 1) - phi, k = k - 1; else, k = k + 1; end
  end
  out.phi_toggle1 = c(k);
  out.phi_toggle2 = c(k + 1);
end
