% Three equilibrium equations, eq. (1): unknowns R_k along each link.
n = size(links, 1);
A = zeros(3, n);
for k = 1:n
  e = links(k, 3:4) / norm(links(k, 3:4));
  A(:, k) = [e(1); e(2); links(k, 1) * e(2) - links(k, 2) * e(1)];
end
b = [0; 0; -C];
for i = 1:size(loads, 1)
  p = loads(i, :);
  b = b - [p(3); p(4); p(1) * p(4) - p(2) * p(3)];
end
if n ~= 3 || rank(A) < 3
  error('improperly supported or statically indeterminate: rank %d with %d links', rank(A), n);
end
R = A \ b;
for k = 1:n
  out.(sprintf('R%d', k)) = R(k);
end
