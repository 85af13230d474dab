// The Vue example of the README (Viewer.vue and vite.config.ts, the README's text) in a page of its own.
import { createApp } from 'vue';
import Viewer from './Viewer.vue';

createApp(Viewer).mount('#app');
