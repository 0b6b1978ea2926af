// Entry point: styles, then the app.

import "./style.css";
import { App } from "./app/app";

const app = new App();
void app.start();
