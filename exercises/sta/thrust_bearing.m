% Friction torque of a collar, eqs. (1)-(4).
out.M_new = 2 / 3 * mu * P * (R2^2 + R1 * R2 + R1^2) / (R1 + R2);  % uniform pressure; (2) with R2 - R1 divided out
out.M_worn = 1 / 2 * mu * P * (R1 + R2);                        % uniform wear
C = P / (2 * pi * (R2 - R1));                                   % p r = C when worn
if strcmp(wear, 'worn')
  out.M = out.M_worn;
  if R1 > 0, out.p_max = C / R1; end
  p = @(r) C ./ r;
else
  out.M = out.M_new;
  out.p_max = P / (pi * (R2 - R1) * (R2 + R1));   % no cancellation for a thin ring
  p = @(r) out.p_max + 0 * r;
end
if mu > 0, out.r_eff = out.M / (mu * P); end
% the integrals (1) by the trapezoidal rule on 2000 rings, for comparison
r = linspace(R1, R2, 2001);
if R1 == 0, r = r(2:end); end
fprintf('load %.10g N, torque %.10g N m (trapezoidal rule)\n', ...
        trapz(r, p(r) .* 2 * pi .* r), trapz(r, mu * p(r) .* 2 * pi .* r.^2));
