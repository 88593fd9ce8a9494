import { defineConfig } from "vite";
import react from "@vitejs/plugin-react";

// The bundle is served by `sceml edit` from the server root, so assets are referenced relatively.
// In development, `npm run dev` proxies /api to a running `sceml edit --port 8765`.
export default defineConfig({
  plugins: [react()],
  base: "./",
  build: {
    outDir: "../src/sceml/editor/static",
    emptyOutDir: true,
    chunkSizeWarningLimit: 2000,
  },
  server: {
    proxy: { "/api": "http://127.0.0.1:8765" },
  },
});
