% Two harmonics: x = A1 cos(omega1 t + phi1) + A2 cos(omega2 t + phi2), eq. (1).
dw = abs(omega1 - omega2);
if dw > 0
  out.beat_period = 2*pi/dw;
  out.beat_frequency = dw/(2*pi);
end
out.carrier_omega = (omega1 + omega2)/2;
out.envelope_max = A1 + A2;                % eq. (4)
out.envelope_min = abs(A1 - A2);
% periodic when omega1/omega2 = p/q (q <= 1000) to the rounding of the data, eq. (6)
[p, q] = rat(omega1/omega2, 4*eps*omega1/omega2);
out.periodic = q <= 1000 && abs(p/q - omega1/omega2) <= 4*eps*omega1/omega2;
if out.periodic
  out.period = 2*pi*p/omega1;
end
t = linspace(0, t_end, points);
x = A1*cos(omega1*t + phi1) + A2*cos(omega2*t + phi2);
E = abs(A1 + A2*exp(1i*((omega2 - omega1)*t + phi2 - phi1)));  % envelope, eq. (4)
% carrier peaks: zeros of x' between 8 points a period of the faster one,
% refined by bisection (all brackets at once)
dx = @(t) -A1*omega1*sin(omega1*t + phi1) - A2*omega2*sin(omega2*t + phi2);
ts = linspace(0, t_end, ceil(8*t_end*max(omega1, omega2)/(2*pi)) + 9);
d = dx(ts);
i = find(d(1:end - 1).*d(2:end) < 0);
a = ts(i); b = ts(i + 1); fa = d(i);
for it = 1:60
  mid = (a + b)/2; fm = dx(mid);
  left = fa.*fm <= 0;
  b(left) = mid(left); a(~left) = mid(~left); fa(~left) = fm(~left);
end
tp = (a + b)/2;
tp = tp(-A1*omega1^2*cos(omega1*tp + phi1) - A2*omega2^2*cos(omega2*tp + phi2) < 0);   % maxima of x
if ~isempty(tp)
  peaks = A1*cos(omega1*tp + phi1) + A2*cos(omega2*tp + phi2);
  out.peak_max = max(peaks);
  out.peak_min = min(peaks);
end
