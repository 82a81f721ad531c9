% A particle on the path x(t), y(t): velocity and acceleration (1) by
% differences, the averages (2), and the error of a difference against its step.
r = @(s) [x(s); y(s)];
% Richardson extrapolation of the central difference: D(h) = r' + c h^2 + ...
% so (4 D(h/2) - D(h)) / 3 cancels the h^2 term (one step of Ridders' method)
D1 = @(s, h) (r(s + h) - r(s - h)) / (2*h);
D2 = @(s, h) (r(s + h) - 2*r(s) + r(s - h)) / h^2;
h = 1e-3;
v = (4*D1(t, h/2) - D1(t, h)) / 3;
a = (4*D2(t, h/2) - D2(t, h)) / 3;
p = r(t);
out.x = p(1);  out.y = p(2);
out.vx = v(1);  out.vy = v(2);  out.v = norm(v);
out.ax = a(1);  out.ay = a(2);  out.a = norm(a);
% averages over [t, t + dt] (2)
va = (r(t + dt) - r(t)) / dt;
v2 = (4*D1(t + dt, h/2) - D1(t + dt, h)) / 3;
aa = (v2 - v) / dt;
out.v_avg_x = va(1);  out.v_avg_y = va(2);
out.a_avg_x = aa(1);  out.a_avg_y = aa(2);
% the plain central difference against the extrapolated one, step by step:
% the error falls like h^2 until rounding (about eps/h) takes over
for k = 1:8
  hk = 10^(-k);
  fprintf('h = %.0e: |D(h) - v| = %.2e\n', hk, norm(D1(t, hk) - v));
end
