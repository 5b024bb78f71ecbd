// extension.js with stand-ins for the vscode API and the language client: it starts the server
// command from the `edsconv.server.command` setting for documents of the language "eds".
"use strict";

const test = require("node:test");
const assert = require("node:assert");
const Module = require("node:module");
const path = require("node:path");

function loadExtension(stubs) {
  const original = Module._load;
  Module._load = function (request, parent, isMain) {
    if (request in stubs) return stubs[request];
    return original.call(this, request, parent, isMain);
  };
  try {
    const file = path.join(__dirname, "..", "extension.js");
    delete require.cache[file];
    return require(file);
  } finally {
    Module._load = original;
  }
}

test("activate starts the configured server for EDS documents", async () => {
  const started = [];
  class LanguageClient {
    constructor(id, name, serverOptions, clientOptions) {
      Object.assign(this, { id, name, serverOptions, clientOptions });
    }
    async start() { started.push(this); }
    async stop() {}
    dispose() {}
  }
  const vscode = {
    workspace: { getConfiguration: (section) => ({ get: (key) => {
      assert.strictEqual(`${section}.${key}`, "edsconv.server.command");
      return ["/venv/bin/edsconv", "lsp"];
    } }) },
    window: { showErrorMessage: (message) => assert.fail(message) },
  };
  const extension = loadExtension({ vscode, "vscode-languageclient/node": { LanguageClient } });
  const context = { subscriptions: [] };
  await extension.activate(context);
  assert.strictEqual(started.length, 1);
  assert.deepStrictEqual(started[0].serverOptions, { command: "/venv/bin/edsconv", args: ["lsp"] });
  assert.deepStrictEqual(started[0].clientOptions.documentSelector, [{ language: "eds" }]);
  assert.deepStrictEqual(context.subscriptions, [started[0]]);
});

test("a server that cannot start is reported, not thrown", async () => {
  const shown = [];
  class LanguageClient {
    async start() { throw new Error("spawn edsconv ENOENT"); }
    dispose() {}
  }
  const vscode = {
    workspace: { getConfiguration: () => ({ get: () => ["edsconv", "lsp"] }) },
    window: { showErrorMessage: (message) => shown.push(message) },
  };
  const extension = loadExtension({ vscode, "vscode-languageclient/node": { LanguageClient } });
  await extension.activate({ subscriptions: [] });
  assert.strictEqual(shown.length, 1);
  assert.match(shown[0], /pip install 'edsconv\[lsp\]'.*ENOENT/);
});
