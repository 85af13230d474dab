// The React example of the README (Viewer.tsx, the README's text) in a page of its own.
import { createRoot } from 'react-dom/client';
import { Viewer } from './Viewer';

createRoot(document.getElementById('app')!).render(<Viewer />);
