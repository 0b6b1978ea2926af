import { describe, expect, test } from "vitest";
import { ProtocolError, parseServerMessage } from "../../src/protocol/messages";
import { ServerError, describeError } from "../../src/protocol/errors";

describe("parseServerMessage", () => {
  test("hello with commands and limits (defaults for missing limits)", () => {
    const m = parseServerMessage(
      JSON.stringify({
        type: "hello",
        protocol: 1,
        server: "s",
        commands: { load: true, study: false },
      }),
    );
    expect(m).toEqual({
      type: "hello",
      protocol: 1,
      server: "s",
      commands: { load: true, study: false },
      keys: {},
      limits: { max_text_bytes: 1048576, max_upload_bytes: 268435456, progress_per_second: 10 },
      upload_suffixes: [],
    });
  });

  test("hello keeps the upload suffixes the server reads", () => {
    const m = parseServerMessage(
      JSON.stringify({
        type: "hello",
        protocol: 1,
        commands: {},
        upload_suffixes: [".obj", ".e57", 3, ".frame.json"],
      }),
    );
    expect(m).toMatchObject({ upload_suffixes: [".obj", ".e57", ".frame.json"] });
  });

  test("hello keeps key declarations, top-level or per command", () => {
    const declaration = { num_rays_per_vp: { default: 30000, min: 1 } };
    const m = parseServerMessage(
      JSON.stringify({
        type: "hello",
        protocol: 1,
        commands: { cloud_occlusion: { keys: declaration }, ping: true },
        keys: { scan: { point_radius: { default: 0.05 } } },
      }),
    );
    const fromJobs = parseServerMessage(
      JSON.stringify({
        type: "hello",
        protocol: 1,
        commands: { cloud_occlusion: true },
        jobs: {
          cloud_occlusion: {
            section: "occlusion.point_cloud",
            keys: [{ name: "seed", default: 0 }],
          },
        },
      }),
    );
    expect(fromJobs).toMatchObject({
      keys: { cloud_occlusion: { seed: { name: "seed", default: 0 } } },
    });
    expect(m).toMatchObject({
      commands: { cloud_occlusion: true, ping: true },
      keys: { cloud_occlusion: declaration, scan: { point_radius: { default: 0.05 } } },
    });
  });

  test("progress is clamped to [0, 1]", () => {
    expect(
      parseServerMessage('{"type":"progress","id":3,"stage":"x","fraction":-2}'),
    ).toMatchObject({ fraction: 0 });
  });

  test("result frames are checked", () => {
    expect(() =>
      parseServerMessage('{"type":"result","id":1,"result":{},"frames":[{"kind":1}]}'),
    ).toThrow(/result frame 0: 'kind' is not a string/);
  });

  test("error with a null id", () => {
    expect(
      parseServerMessage('{"type":"error","id":null,"code":"invalid_json","message":"m"}'),
    ).toEqual({
      type: "error",
      id: null,
      code: "invalid_json",
      message: "m",
    });
  });

  test.each([
    ["not JSON", "{", /not JSON/],
    ["an array", "[]", /not a JSON object/],
    ["no type", "{}", /unknown message type undefined/],
    ["hello without protocol", '{"type":"hello","commands":{}}', /hello without 'protocol'/],
    ["a negative id", '{"type":"result","id":-1,"result":{}}', /valid 'id'/],
    ["an id over 32 bits", '{"type":"progress","id":4294967296,"fraction":0}', /valid 'id'/],
    [
      "a result that is not an object",
      '{"type":"result","id":1,"result":3}',
      /without a 'result' object/,
    ],
  ])("rejects %s", (_, text, message) => {
    expect(() => parseServerMessage(text)).toThrow(ProtocolError);
    expect(() => parseServerMessage(text)).toThrow(message);
  });
});

describe("describeError", () => {
  test("server errors read as a sentence with the code and the server's message", () => {
    const d = describeError(
      new ServerError("input_error", "uploads/x.ply:3: bad number", "upload"),
      "Uploading x.ply",
    );
    expect(d.title).toBe("Uploading x.ply failed: the file could not be read.");
    expect(d.detail).toBe("input_error: uploads/x.ply:3: bad number");
  });

  test("unknown codes and plain errors still give a message", () => {
    expect(describeError(new ServerError("weird", "m", "scan")).title).toBe(
      "scan failed: the server reported an error.",
    );
    expect(describeError(new Error("boom"), "Showing x")).toMatchObject({
      title: "Showing x failed",
      detail: "boom",
    });
  });
});
