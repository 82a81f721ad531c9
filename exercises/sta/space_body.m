% Six equilibrium equations, eq. (1): columns (e_k, p_k x e_k).
n = size(links, 1);
A = zeros(6, n);
for k = 1:n
  p = links(k, 1:3);
  e = links(k, 4:6) / norm(links(k, 4:6));
  A(:, k) = [e'; cross(p, e)'];
end
Wl = zeros(6, 1);                   % the loads as one force and one moment
for i = 1:size(loads, 1)
  Wl = Wl + [loads(i, 4:6)'; cross(loads(i, 1:3), loads(i, 4:6))'];
end
if n ~= 6 || rank(A) < 6
  error('improperly supported or statically indeterminate: rank %d with %d links', rank(A), n);
end
R = A \ (-Wl);
% the same by virtual work, eqs. (3)-(4): the motion that stretches link k alone
Xi = A' \ eye(6);
Rvw = -(Wl' * Xi)';
for k = 1:n
  out.(sprintf('R%d', k)) = R(k);
  fprintf('link %d: %.10g N (virtual work %.10g N)\n', k, R(k), Rvw(k));
end
