% A particle on the path x(t), y(t): velocity and acceleration (1) by
% differences, the averages (2), and the error of a difference against its step.
r = @(s) [x(s); y(s)];
D1 = @(s, h) (r(s + h) - r(s - h)) / (2*h);          % error h^2/6 r''' + ...
D2 = @(s, h) (r(s + h) - 2*r(s) + r(s - h)) / h^2;   % error h^2/12 r'''' + ...
% Richardson's extrapolation: D(h) = d + c2 h^2 + c4 h^4 + ..., so
% (4 D(h/2) - D(h))/3 cancels h^2 and (16 R(h/2) - R(h))/15 then h^4
rich = @(Dh, Dh2, Dh4) (16*(4*Dh4 - Dh2)/3 - (4*Dh2 - Dh)/3) / 15;
h1 = 0.02;  h2 = 0.04;                                % steps for r' and r''
v = rich(D1(t, h1), D1(t, h1/2), D1(t, h1/4));
a = rich(D2(t, h2), D2(t, h2/2), D2(t, h2/4));
p = r(t);
out.x = p(1);  out.y = p(2);
out.vx = v(1);  out.vy = v(2);  out.v = norm(v);
out.ax = a(1);  out.ay = a(2);  out.a = norm(a);
% averages over [t, t + dt] (2)
t2 = t + dt;  span = t2 - t;
va = (r(t2) - r(t)) / span;
v2 = rich(D1(t2, h1), D1(t2, h1/2), D1(t2, h1/4));
aa = (v2 - v) / span;
out.v_avg_x = va(1);  out.v_avg_y = va(2);
out.a_avg_x = aa(1);  out.a_avg_y = aa(2);
% the plain central difference against the extrapolated one, step by step:
% the error falls like h^2 until rounding (about eps/h) takes over
for k = 1:8
  hk = 10^(-k);
  fprintf('step %.0e: |D(h) - v| = %.2e\n', hk, norm(D1(t, hk) - v));
end
