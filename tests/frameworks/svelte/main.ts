// The Svelte example of the README (Viewer.svelte, the README's text) in a page of its own.
import { mount } from 'svelte';
import Viewer from './Viewer.svelte';

mount(Viewer, { target: document.getElementById('app')! });
