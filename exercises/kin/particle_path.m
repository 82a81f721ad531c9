% A particle on the path x(t), y(t): velocity and acceleration (1) by
% Ridders' extrapolation of central differences, the averages (2), and the
% error of a plain central difference against its step.
r = @(s) [x(s); y(s)];
h0 = 0.05 * min(t1 - t0, 1);               % the first step
t2 = t + dt;  span = t2 - t;
for pass = 1:2                             % at t, then at t + dt
  if pass == 1, tt = t; else, tt = t2; end
  % central differences D1 (first) and D2 (second) at h0, h0/1.4, h0/1.4^2, ...
  f0 = r(tt);  Dv = zeros(2, 10);  Da = zeros(2, 10);  hh = h0;
  for i = 1:10
    tp = tt + hh;  tm = tt - hh;  hs = (tp - tm) / 2;   % the steps actually taken
    fp = r(tp);  fm = r(tm);
    Dv(:, i) = (fp - fm) / (2*hs);
    Da(:, i) = (fp - 2*f0 + fm) / hs^2;
    hh = hh / 1.4;
  end
  % each extrapolated to h = 0 in a Neville table (the error is even in h):
  % the entry that agrees best with its neighbours is kept
  d = zeros(2, 2);                         % rows x, y; columns r', r''
  for o = 1:2
    for c = 1:2
      if o == 1, Dr = Dv(c, :); else, Dr = Da(c, :); end
      tab = zeros(10);  tab(1, 1) = Dr(1);  err = Inf;  best = Dr(1);
      for i = 2:10
        tab(1, i) = Dr(i);  fac = 1.96;
        for j = 2:i
          tab(j, i) = (tab(j - 1, i)*fac - tab(j - 1, i - 1)) / (fac - 1);
          fac = fac * 1.96;
          ej = max(abs(tab(j, i) - tab(j - 1, i)), abs(tab(j, i) - tab(j - 1, i - 1)));
          if ej <= err, err = ej; best = tab(j, i); end
        end
        if i >= 5 && abs(tab(i, i) - tab(i - 1, i - 1)) >= 2*err
          break                            % rounding has taken over
        end
      end
      d(c, o) = best;
    end
  end
  if pass == 1, v = d(:, 1); a = d(:, 2); else, v2 = d(:, 1); end
end
p = r(t);
out.x = p(1);  out.y = p(2);
out.vx = v(1);  out.vy = v(2);  out.v = norm(v);
out.ax = a(1);  out.ay = a(2);  out.a = norm(a);
% averages over [t, t + dt] (2)
va = (r(t2) - r(t)) / span;
out.v_avg_x = va(1);  out.v_avg_y = va(2);
out.a_avg_x = (v2(1) - v(1)) / span;  out.a_avg_y = (v2(2) - v(2)) / span;
% the plain central difference against Ridders, step by step: the error
% falls like h^2 until rounding (about eps/h) takes over
for k = 1:8
  hk = 10^(-k);
  fprintf('step %.0e: |D(h) - v| = %.2e\n', hk, norm((r(t + hk) - r(t - hk)) / (2*hk) - v));
end
