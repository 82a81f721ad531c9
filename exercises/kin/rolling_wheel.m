% A wheel rolling without slipping: position (1), velocity (2) and
% acceleration (3) of a point P at distance b from the centre.
phi = omega*t + 0.5*alpha*t^2;   phid = omega + alpha*t;   phidd = alpha;
O = [R*phi; R];                                  % the centre
P = O + b*[-sin(phi); -cos(phi)];                % (1)
g = [R - b*cos(phi); b*sin(phi)];                % dP/dphi
v = phid * g;                                    % (2)
a = phidd * g + phid^2 * [b*sin(phi); b*cos(phi)];   % (3)
out.v_O = phid * R;
out.x = P(1);  out.y = P(2);
out.vx = v(1);  out.vy = v(2);  out.v = norm(v);
out.ax = a(1);  out.ay = a(2);  out.a = norm(a);
% the contact point C as a point of the wheel: v_O + w x (C - O), w = -phid k
vC = [phid*R; 0] + (-phid) * [R; 0];             % k x (0, -R) = (R, 0)
out.v_contact = norm(vC);                        % exactly 0
out.a_contact = phid^2 * R;                      % upward
% the instantaneous centre is C: |v_P| = |phid| |P - C|
fprintf('|v_P| = %.15g, |phid| |PC| = %.15g\n', norm(v), abs(phid)*norm(P - [R*phi; 0]));
cr = abs(v(1)*a(2) - v(2)*a(1));
if cr > 0
  out.rho = norm(v)^3 / cr;
end
if b > 0
  out.rho_top = (R + b)^2 / b;
  % one arch: the integral of |dP/dphi| over a turn, against 4 (R+b) E(k)
  k = 2*sqrt(R*b) / (R + b);
  % E(k) by the arithmetic-geometric mean (Abramowitz & Stegun 17.6)
  aa = 1;  gg = sqrt(1 - k^2);  c = k;  s = c^2/2;  p2 = 1/2;
  while abs(c) > eps*aa
    c = (aa - gg)/2;  an = (aa + gg)/2;  gg = sqrt(aa*gg);  aa = an;
    p2 = 2*p2;  s = s + p2*c^2;
  end
  E = pi/(2*aa) * (1 - s);
  if b == R
    E = 1;                                       % the cycloid: L = 8 R
  end
  out.arch_length = 4*(R + b)*E;
  % the trapezoid rule on 2000 steps as a check
  ph = linspace(0, 2*pi, 2001);
  f = sqrt((R - b)^2 + 4*R*b*sin(ph/2).^2);
  L = (sum(f) - (f(1) + f(end))/2) * (ph(2) - ph(1));
  fprintf('arch length: closed form %.15g, quadrature %.15g\n', out.arch_length, L);
end
