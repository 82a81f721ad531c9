// Exercise extensions: an exercise whose page needs more than the generated
// form (a truss drawn with the mouse, say) registers a module here, loaded
// only on its own page.
//
// The contract (web/js/exercise.js keeps it):
//   module.mount(host, api) is called once, after the first answer, with
//     host  an empty <div class="extension"> placed beside the figures;
//     api   { getParams()      -> {name: text} of the values in the form,
//             setParams(obj)   -> set some values (text, as in a query
//                                 string) and solve again, as if typed,
//             onAnswer(cb)     -> cb(answer) after every answer (also now);
//                                 a refusal as its body, {error: {code, param, message}},
//             lang             -> the page's language, 'en' | 'cs' | 'de' }.
//   mount may return a function that undoes it (called on page teardown).
// Extensions talk to the server only through the public API, like the page.
export const extensions = {
  'sta-truss': () => import('./sta-truss.js?v=__MM_ASSET_VERSION__'),
};
