% Tangential and normal coordinates along the path x(t), y(t): speed,
% a_t, a_n, curvature and the centre of curvature (1)-(2).
r = @(s) [x(s); y(s)];
D1 = @(s, h) (r(s + h) - r(s - h)) / (2*h);
D2 = @(s, h) (r(s + h) - 2*r(s) + r(s - h)) / h^2;
% Richardson's extrapolation to h = 0, two steps (errors h^2 and h^4 cancelled)
rich = @(Dh, Dh2, Dh4) (16*(4*Dh4 - Dh2)/3 - (4*Dh2 - Dh)/3) / 15;
v = rich(D1(t, 0.02), D1(t, 0.01), D1(t, 0.005));
a = rich(D2(t, 0.04), D2(t, 0.02), D2(t, 0.01));
out.v = norm(v);
out.a = norm(a);
T = v / out.v;                             % unit tangent
N = [-T(2); T(1)];                         % unit normal, to the left
cr = v(1)*a(2) - v(2)*a(1);                % v x a
out.a_t = dot(v, a) / out.v;               % (2)
out.a_n = abs(cr) / out.v;
out.kappa = cr / out.v^3;
out.direction = atan2(T(2), T(1));
if out.kappa ~= 0
  out.rho = 1 / abs(out.kappa);
  C = r(t) + N / out.kappa;                % centre of curvature
  out.centre_x = C(1);  out.centre_y = C(2);
end
% check: a_t is the rate of change of the speed
sp = @(s) norm(rich(D1(s, 0.02), D1(s, 0.01), D1(s, 0.005)));
fprintf('check: a_t %.10g, d|v|/dt by a central difference %.10g\n', out.a_t, (sp(t + 1e-3) - sp(t - 1e-3)) / 2e-3);
