% The double pendulum: Lagrange's equations, the energy of two integrators, two twins.
M = m1 + m2;
% the small oscillation, eq. (4): det(K - w^2 M0) = 0
M0 = [M*l1^2, m2*l1*l2; m2*l1*l2, m2*l2^2];  K = diag([M*g*l1, m2*g*l2]);
w2 = sort(eig(K, M0));
out.omega_slow = sqrt(w2(1));  out.omega_fast = sqrt(w2(2));
% Lagrange's equations (2)-(3) solved for the accelerations; y = [th1; th2; w1; w2]
acc = @(y) [M*l1, m2*l2*cos(y(1)-y(2)); l1*cos(y(1)-y(2)), l2] \ ...
           [-m2*l2*sin(y(1)-y(2))*y(4)^2 - M*g*sin(y(1)); l1*sin(y(1)-y(2))*y(3)^2 - g*sin(y(2))];
f = @(t, y) [y(3); y(4); acc(y)];
E = @(y) M*l1^2*y(3)^2/2 + m2*l2^2*y(4)^2/2 + m2*l1*l2*y(3)*y(4)*cos(y(1)-y(2)) ...
         - M*g*l1*cos(y(1)) - m2*g*l2*cos(y(2));
y0 = [theta1_0; theta2_0; omega1_0; omega2_0];
Vmin = -M*g*l1 - m2*g*l2;  Es = max(-2*Vmin, E(y0) - Vmin);
out.E0 = E(y0) - Vmin;
% Dormand-Prince 5(4) (ode45) at rtol lets the energy drift; try
%   [t, y] = ode45(f, [0 t_end], y0, odeset('RelTol', rtol, 'AbsTol', rtol));
% and plot E along it (left out here: a long run is slow in Octave)
% a symplectic method on Hamilton's equations (5), in theta and p = M(theta) w:
% Gauss-Legendre collocation, the stage equations solved by fixed-point iteration
Mm = @(q) [M*l1^2, m2*l1*l2*cos(q(1)-q(2)); m2*l1*l2*cos(q(1)-q(2)), m2*l2^2];
vel = @(z) Mm(z(1:2)) \ z(3:4);
pdot = @(q, w) Mm(q) * acc([q; w]) - m2*l1*l2*sin(q(1)-q(2)) * (w(1)-w(2)) * [w(2); w(1)];
ham = @(z) [vel(z); pdot(z(1:2), vel(z))];
if strcmp(symplectic, 'gauss4')
  A = [1/4, 1/4 - sqrt(3)/6; 1/4 + sqrt(3)/6, 1/4];  b = [1/2, 1/2];
else
  A = 1/2;  b = 1;                        % the implicit midpoint rule
end
z = [y0(1:2); Mm(y0(1:2)) * y0(3:4)];  n = ceil(t_end / h);  hh = t_end / n;  dE = 0;
if n > 300
  n = 0;                                  % a long run is slow in Octave: left to the server
  disp('the symplectic run is skipped here: more than 300 steps');
end
for k = 1:n
  Kst = repmat(ham(z), 1, numel(b));
  for it = 1:100
    Kold = Kst;
    for i = 1:numel(b)
      Kst(:, i) = ham(z + hh * Kst * A(i, :)');
    end
    if max(abs(Kst(:) - Kold(:))) <= 1e-15 * max(abs(Kst(:)))
      break;
    end
  end
  z = z + hh * Kst * b';
  dE = max(dE, abs(E([z(1:2); vel(z)]) - E(y0)) / Es);
end
fprintf('symplectic: largest relative energy error %.3g\n', dE);
% the twin, started separation apart, over at most 40 fast periods:
% the slope of log distance estimates the Lyapunov exponent, eq. (6)
t_ly = min(t_end, 40 * 2 * pi / out.omega_fast);
tg = linspace(0, t_ly, points)';
% both twins in one run: the same steps for both, so that their errors
% largely cancel in the difference
opts = odeset('RelTol', 1e-11, 'AbsTol', 1e-12);
[~, Y] = ode45(@(t, Y) [f(t, Y(1:4)); f(t, Y(5:8))], tg, [y0; y0 + [0; separation; 0; 0]], opts);
ya = Y(:, 1:4);  yb = Y(:, 5:8);
d = sqrt(sum([ya(:, 1:2) - yb(:, 1:2), (ya(:, 3:4) - yb(:, 3:4)) / out.omega_fast].^2, 2));
ilo = find(d > 1e3 * separation, 1);
ihi = find(d > 1e-3, 1);
if ~isempty(ihi)
  % the prediction horizon: where d = 1e-3, interpolating log d
  out.t_horizon = tg(ihi - 1) + (tg(ihi) - tg(ihi - 1)) * log(1e-3 / d(ihi - 1)) / log(d(ihi) / d(ihi - 1));
else
  ihi = numel(tg) + 1;
end
if ~isempty(ilo) && ihi > ilo + 8
  c = polyfit(tg(ilo:ihi - 1), log(d(ilo:ihi - 1)), 1);
  out.lyapunov = c(1);
end
