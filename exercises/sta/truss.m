% Method of joints: two equations per joint (sum Fx = 0, sum Fy = 0),
% one unknown per member force (tension positive) and per reaction.
nj = size(nodes, 1);
nm = size(members, 1);
nr = sum(sum(supports(:, 2:3)));
A = zeros(2 * nj, nm + nr);
b = zeros(2 * nj, 1);
for e = 1:nm
  i = members(e, 1);
  j = members(e, 2);
  d = nodes(j, :) - nodes(i, :);
  u = d / norm(d);                  % unit vector from joint i to joint j
  A(2*i-1:2*i, e) = u';             % a member in tension pulls i toward j
  A(2*j-1:2*j, e) = -u';            % and j toward i
end
k = nm;
for s = 1:size(supports, 1)
  for c = 1:2                       % c = 1: fixed in x, c = 2: fixed in y
    if supports(s, 1 + c) == 1
      k = k + 1;
      A(2 * (supports(s, 1) - 1) + c, k) = 1;
    end
  end
end
for l = 1:size(loads, 1)
  n = loads(l, 1);
  b(2*n-1:2*n) = b(2*n-1:2*n) - loads(l, 2:3)';
end
out.determinacy = nm + nr - 2 * nj;
out.n_joints = nj;
out.n_members = nm;
out.n_reactions = nr;
if out.determinacy ~= 0 || rank(A) < 2 * nj
  error('not determinate: a mechanism (rank < 2j) or statically indeterminate (m + r > 2j)');
end
x = A \ b;
F = x(1:nm);
for e = 1:nm
  fprintf('member %d (joints %d-%d): %.6g N\n', e, members(e, 1), members(e, 2), F(e));
end
out.max_tension = max([F; 0]);
out.max_compression = min([F; 0]);
